// SPDX-License-Identifier: Zlib
#include <btFracture/core/FractureSettings.h>

#include <btFracture/core/Error.h>

#include <cmath>
#include <sstream>

namespace btfracture {
namespace {

// "<where>: <field> <value> (need <range>)"
void require(bool ok, const std::string& where, const char* field, double value, const char* range) {
    if (ok) return;
    std::ostringstream msg;
    msg << where << ": " << field << " " << value << " (need " << range << ")";
    throw Error(msg.str());
}

}  // namespace

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

void MaterialNoise::validate(const std::string& where) const {
    require(amplitude >= 0.0 && amplitude < 1.0, where, "materialNoise.amplitude", amplitude, "[0, 1)");
    require(wavelength > 0.0 && std::isfinite(wavelength), where, "materialNoise.wavelength", wavelength,
            "finite, > 0 m");
}

void FractureMethodSettings::validate(const std::string& where) const {
    require(hybridElementThreshold >= 1, where, "hybridElementThreshold", hybridElementThreshold, ">= 1");
    require(crackElementSize >= 0.0 && std::isfinite(crackElementSize), where, "crackElementSize",
            crackElementSize, "finite, >= 0 m; 0 = the BEM mesh's");
}

void CrackSettings::validate(const std::string& where) const {
    require(maxNewCracksPerEvent >= 0, where, "maxNewCracksPerEvent", maxNewCracksPerEvent, ">= 0");
    require(maxStepsPerEvent >= 0, where, "maxStepsPerEvent", maxStepsPerEvent, ">= 0");
    require(seedRadius > 0.0 && seedRadius <= 2.0, where, "seedRadius", seedRadius, "(0, 2]");
    require(frontEdgeLength > 0.05 && frontEdgeLength <= 4.0, where, "frontEdgeLength", frontEdgeLength,
            "(0.05, 4]");
    require(minimumSpeed > 0.0 && minimumSpeed <= 1.0, where, "minimumSpeed", minimumSpeed, "(0, 1]");
    require(estimatorGeometryFactor > 0.0 && std::isfinite(estimatorGeometryFactor), where,
            "estimatorGeometryFactor", estimatorGeometryFactor, "finite, > 0");
    require(estimatorUpdateGainLimit == 0.0 || estimatorUpdateGainLimit >= 1.0, where,
            "estimatorUpdateGainLimit", estimatorUpdateGainLimit, "0 = off, or >= 1");
}

void FractureSettings::validate() const {
    CrackSettings::validate("fracture settings");
    FractureMethodSettings::validate("fracture settings");
}

}  // namespace btfracture
