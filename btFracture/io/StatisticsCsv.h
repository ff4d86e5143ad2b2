// SPDX-License-Identifier: Zlib
#pragma once
// The statistics CSV: one row per fracture event. The fracture world's listener
// (io/FractureRecorderListener.h) fills a FractureEventRecord per event and hands it to
// FractureRecorder (io/FractureRecorder.h), which names the fragments and calls StatisticsCsv::add.
#include <btFracture/dynamics/FractureEnergy.h>
#include <btFracture/io/SceneFile.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace btfracture {

struct FractureEventRecord {
    std::uint64_t worldEvent = 0;  // the world's event counter (FractureEventInfo::event)
    std::uint64_t step = 0;        // the world's internal Bullet step at the event
    double time = 0.0;             // simulated time at the start of that step [s]
    std::string body;              // the body that broke
    int contacts = 0;              // contacts that loaded it
    double impulse = 0.0;          // summed normal contact impulse on it [N s]
    // Hertz contact duration t_c that turned impulses into tractions (§5.1); the longest over the
    // contacts [s].
    double contactDuration = 0.0;
    // The body's fracture method.
    FractureMethod method = FractureMethod::Full;
    int bemTriangles = 0;                // BEM surface mesh of the body
    int crackTriangles = 0;              // crack-sheet triangles at the end of the event
    std::vector<std::string> fragments;  // names of the bodies that replaced it
    double fractureSeconds = 0.0;        // wall time in the fracture solver [s]
    double swapSeconds = 0.0;            // wall time restoring, swapping bodies and replaying the step [s]
    // The event's energy audit (dynamics/FractureEnergy.h); its columns stay empty without one.
    bool hasEnergy = false;
    FractureEnergyAudit energy;
};

class StatisticsCsv {
public:
    // Creates (truncates) `path` and writes the header line:
    //   event,step,time_s,body,contacts,impulse_Ns,contact_duration_s,method,bem_triangles,
    //   crack_triangles,fragments,fragment_names,fracture_wall_s,swap_wall_s,
    //   ke_body_J,ke_partners_J,ke_swap_J,ke_separated_J,pe_gain_swap_J,pe_gain_separated_J,
    //   ke_replay_J,ke_following_max_J,
    //   following_steps,world_energy_before_J,world_energy_gain_J,energy_added_fraction
    // The energy columns are FractureEnergyAudit's fields (kinetic energies of the breaking body,
    // the bodies touching it, its fragments at each stage; the fragments' potential energy above
    // the body's; the largest rise of the world's mechanical energy and that rise over
    // ke_body_J + ke_partners_J).
    // fragment_names is space-separated. Fields with a comma, quote or line break are quoted
    // (RFC 4180). Numbers use 9 significant digits; every column except the two *_wall_s ones is
    // the same in every run of the same scene; `wallTimes` false leaves those two empty, so that
    // the whole file is. Throws btfracture::Error naming the path when the file cannot be created.
    explicit StatisticsCsv(std::string path, bool wallTimes = true);
    StatisticsCsv(const StatisticsCsv&) = delete;
    StatisticsCsv& operator=(const StatisticsCsv&) = delete;
    ~StatisticsCsv();

    // Appends one row (flushed, so that a crashed run keeps the events so far).
    void add(const FractureEventRecord& record);
    int rows() const { return rows_; }
    const std::string& path() const { return path_; }
    // Closes the file; throws Error naming the path when writing failed.
    void close();

private:
    std::string path_;
    std::ofstream out_;
    int rows_ = 0;
    bool wallTimes_ = true;
    bool closed_ = false;
};

// One CSV field: as it is, or quoted with doubled quotes when it holds ',', '"', '\n' or '\r'.
std::string csvField(const std::string& text);

}  // namespace btfracture
