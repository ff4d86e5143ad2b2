// SPDX-License-Identifier: Zlib
#include <btFracture/core/FractureSettings.h>

#include <btFracture/core/Error.h>

#include <cmath>
#include <sstream>

namespace btfracture {

const char* toString(FractureMethod method) {
    switch (method) {
        case FractureMethod::Full:
            return "full";
        case FractureMethod::Estimated:
            return "est";
        case FractureMethod::Hybrid:
            return "hybrid";
    }
    return "?";
}

FractureMethod fractureMethodFromString(const std::string& text) {
    if (text == "full") return FractureMethod::Full;
    if (text == "est" || text == "estimated") return FractureMethod::Estimated;
    if (text == "hybrid") return FractureMethod::Hybrid;
    throw Error("expected \"full\", \"est\" or \"hybrid\", got \"" + text + "\"");
}

void FractureSettings::validate() const {
    auto fail = [](const char* field, double value, const char* expected) {
        std::ostringstream msg;
        msg << "fracture settings: " << field << " = " << value << ", expected " << expected;
        throw Error(msg.str());
    };
    if (hybridElementThreshold < 1) fail("hybridElementThreshold", hybridElementThreshold, ">= 1");
    if (maxNewCracksPerEvent < 0) fail("maxNewCracksPerEvent", maxNewCracksPerEvent, ">= 0");
    if (maxStepsPerEvent < 0) fail("maxStepsPerEvent", maxStepsPerEvent, ">= 0");
    if (!(seedRadius > 0.0 && seedRadius <= 2.0)) fail("seedRadius", seedRadius, "in (0, 2]");
    if (!(frontEdgeLength > 0.05 && frontEdgeLength <= 4.0))
        fail("frontEdgeLength", frontEdgeLength, "in (0.05, 4]");
    if (!(minimumSpeed > 0.0 && minimumSpeed <= 1.0)) fail("minimumSpeed", minimumSpeed, "in (0, 1]");
    if (!(estimatorGeometryFactor > 0.0 && std::isfinite(estimatorGeometryFactor)))
        fail("estimatorGeometryFactor", estimatorGeometryFactor, "positive");
    if (!(estimatorUpdateGainLimit == 0.0 || estimatorUpdateGainLimit >= 1.0))
        fail("estimatorUpdateGainLimit", estimatorUpdateGainLimit, "0 (off) or >= 1");
    if (!(noise.amplitude >= 0.0 && noise.amplitude < 1.0))
        fail("noise.amplitude", noise.amplitude, "in [0, 1)");
    if (!(noise.wavelength > 0.0 && std::isfinite(noise.wavelength)))
        fail("noise.wavelength", noise.wavelength, "positive");
}

}  // namespace btfracture
