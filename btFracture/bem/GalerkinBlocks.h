// SPDX-License-Identifier: Zlib
#pragma once
// The 3x3 Galerkin blocks shared by every assembly (surface K and F, crack blocks C, D, G): the
// hypersingular operator and the adjoint double layer after integration by parts, in terms of
// the surface curls of the hats and the material-independent PairIntegrals (FORMULATION.md).
#include <btFracture/bem/PairIntegrals.h>

#include <cmath>

namespace btfracture {

// Columns of S [v] for symmetric S (s00 s01 s02 s11 s12 s22): column j is S (v x e_j);
// out is column-major 3x3.
inline void symTimesCross(const double* S, const double* v, double* out) {
    const double s[3][3] = {{S[0], S[1], S[2]}, {S[1], S[3], S[4]}, {S[2], S[4], S[5]}};
    for (int i = 0; i < 3; ++i) {
        out[0 + i] = v[2] * s[i][1] - v[1] * s[i][2];
        out[3 + i] = v[0] * s[i][2] - v[2] * s[i][0];
        out[6 + i] = v[1] * s[i][0] - v[0] * s[i][1];
    }
}

// The material-scaled integrals of one pair: a = I0 / 4 pi and L = 4 mu^2 B with
// B = int int U* = ((3 - 4 nu) I0 Id + J) / (16 pi mu (1 - nu)).
struct PairCoefficients {
    double a;
    double L[6];
};

inline PairCoefficients coefficientsOf(const PairIntegrals& pi, double mu, double nu) {
    const double lameScale = mu / (4.0 * M_PI * (1.0 - nu));
    const double diag = lameScale * (3.0 - 4.0 * nu) * pi.inverseDistance;
    return {pi.inverseDistance / (4.0 * M_PI),
            {lameScale * pi.dyadic(0, 0) + diag, lameScale * pi.dyadic(0, 1), lameScale * pi.dyadic(0, 2),
             lameScale * pi.dyadic(1, 1) + diag, lameScale * pi.dyadic(1, 2),
             lameScale * pi.dyadic(2, 2) + diag}};
}

// K block of test hat with curl c against trial hat with curl d, scaled, added to out(i, j):
//   mu a [4 (c.d) Id - 2 d c^T - c d^T] + [c] L [d]     (P = L [d], column-major)
template <class Out>
inline void addStiffnessBlock(const double* c, const double* d, const double* P, double muA, double scale,
                              Out&& out) {
    const double g4 = 4.0 * muA * (c[0] * d[0] + c[1] * d[1] + c[2] * d[2]);
    for (int j = 0; j < 3; ++j) {
        const double* pj = P + 3 * j;
        const double cross[3] = {c[1] * pj[2] - c[2] * pj[1], c[2] * pj[0] - c[0] * pj[2],
                                 c[0] * pj[1] - c[1] * pj[0]};
        for (int i = 0; i < 3; ++i) {
            double v = cross[i] - muA * (2.0 * d[i] * c[j] + c[i] * d[j]);
            if (i == j) v += g4;
            out(i, j, scale * v);
        }
    }
}

// F block of test hat with curl c (on triangle s) against the traction of triangle t:
//   [c] L / (2 mu) - a [c] + (mass - int_t K_Laplace phi) Id,   [c] L = -(L [c])^T
template <class Out>
inline void addLoadBlock(const double* c, const PairCoefficients& k, double mu, double scalar, Out&& out) {
    double Q[9];
    symTimesCross(k.L, c, Q);
    const double cross[3][3] = {{0, -c[2], c[1]}, {c[2], 0, -c[0]}, {-c[1], c[0], 0}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            out(i, j, -Q[3 * i + j] * (0.5 / mu) - k.a * cross[i][j] + (i == j ? scalar : 0.0));
}

}  // namespace btfracture
