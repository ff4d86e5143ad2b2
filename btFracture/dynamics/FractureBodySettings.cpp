// SPDX-License-Identifier: Zlib
#include <btFracture/dynamics/FractureBodySettings.h>

#include <btFracture/core/Error.h>

#include <cmath>
#include <sstream>

namespace btfracture {

void validate(const FractureBodySettings& s, const std::string& body) {
    std::ostringstream problem;
    if (!(s.impulseThreshold >= 0.0) || !std::isfinite(s.impulseThreshold))
        problem << "impulseThreshold " << s.impulseThreshold << " N s (need finite, >= 0)";
    else if (s.hybridElementThreshold < 0)
        problem << "hybridElementThreshold " << s.hybridElementThreshold << " (need >= 0)";
    else if (s.bemTriangleTarget < 4)
        problem << "bemTriangleTarget " << s.bemTriangleTarget << " (need >= 4)";
    else if (s.collisionTriangleTarget < s.bemTriangleTarget)
        problem << "collisionTriangleTarget " << s.collisionTriangleTarget << " (need >= bemTriangleTarget "
                << s.bemTriangleTarget << ")";
    else if (!(s.voxelSize >= 0.0) || !std::isfinite(s.voxelSize))
        problem << "voxelSize " << s.voxelSize << " m (need finite, >= 0)";
    else if (s.maxRefractureDepth < 0)
        problem << "maxRefractureDepth " << s.maxRefractureDepth << " (need >= 0)";
    else if (s.refractureDepth < 0)
        problem << "refractureDepth " << s.refractureDepth << " (need >= 0)";
    else if (!(s.materialNoise.amplitude >= 0.0 && s.materialNoise.amplitude < 1.0))
        problem << "materialNoise.amplitude " << s.materialNoise.amplitude << " (need [0, 1))";
    else if (!(s.materialNoise.wavelength > 0.0) || !std::isfinite(s.materialNoise.wavelength))
        problem << "materialNoise.wavelength " << s.materialNoise.wavelength << " m (need finite, > 0)";
    if (problem.tellp() > 0) throw Error(body + ": fracture settings: " + problem.str());
}

}  // namespace btfracture
