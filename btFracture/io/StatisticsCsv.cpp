// SPDX-License-Identifier: Zlib
#include <btFracture/io/StatisticsCsv.h>

#include <btFracture/core/Error.h>
#include <btFracture/core/Log.h>

#include <cstdio>

namespace btfracture {
namespace {

std::string number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

}  // namespace

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

StatisticsCsv::StatisticsCsv(std::string path, bool wallTimes)
    : path_(std::move(path)), out_(path_, std::ios::binary | std::ios::trunc), wallTimes_(wallTimes) {
    if (!out_) throw Error("cannot create statistics file '" + path_ + "'");
    out_ << "event,step,time_s,body,contacts,impulse_Ns,contact_duration_s,method,bem_triangles,crack_"
            "triangles,"
            "fragments,fragment_names,fracture_wall_s,swap_wall_s,ke_body_J,ke_partners_J,ke_swap_J,ke_"
            "separated_J,"
            "pe_gain_swap_J,pe_gain_separated_J,ke_replay_J,ke_following_max_J,following_steps,world_energy_"
            "before_J,world_energy_gain_J,"
            "energy_added_fraction\n";
    out_.flush();
}

StatisticsCsv::~StatisticsCsv() {
    try {
        close();
    } catch (const Error& e) {
        logf(LogLevel::Error, e.what());
    }
}

void StatisticsCsv::add(const FractureEventRecord& r) {
    if (closed_) throw Error("statistics file '" + path_ + "' is closed");
    std::string names;
    for (const std::string& name : r.fragments) names += (names.empty() ? "" : " ") + name;
    out_ << ++rows_ << ',' << r.step << ',' << number(r.time) << ',' << csvField(r.body) << ',' << r.contacts
         << ',' << number(r.impulse) << ',' << number(r.contactDuration) << ',' << toString(r.method) << ','
         << r.bemTriangles << ',' << r.crackTriangles << ',' << r.fragments.size() << ',' << csvField(names)
         << ',';
    if (wallTimes_)
        out_ << number(r.fractureSeconds) << ',' << number(r.swapSeconds);
    else
        out_ << ',';
    if (r.hasEnergy) {
        const FractureEnergyAudit& e = r.energy;
        out_ << ',' << number(e.bodyKinetic) << ',' << number(e.partnersKinetic) << ','
             << number(e.swapKinetic) << ',' << number(e.separatedKinetic) << ','
             << number(e.swapPotentialGain) << ',' << number(e.separatedPotentialGain) << ','
             << number(e.replayKinetic) << ',' << number(e.followingKinetic) << ',' << e.followingSteps << ','
             << number(e.worldBefore) << ',' << number(e.worldGain) << ',' << number(e.addedFraction());
    } else {
        out_ << ",,,,,,,,,,,,";
    }
    out_ << '\n';
    out_.flush();
    if (!out_) throw Error("writing statistics file '" + path_ + "' failed");
}

void StatisticsCsv::close() {
    if (closed_) return;
    closed_ = true;
    out_.close();
    if (out_.fail()) throw Error("writing statistics file '" + path_ + "' failed");
}

}  // namespace btfracture
