// SPDX-License-Identifier: Zlib
// Fracture statistics: the CSV writer, fragment naming and bookkeeping, and the fragment-volume
// comparison against Mott's distribution.
#include <btFracture/core/Error.h>
#include <btFracture/io/FractureRecorder.h>
#include <btFracture/io/MottHistogram.h>
#include <btFracture/io/StatisticsCsv.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace btfracture;

namespace {

std::filesystem::path scratch(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / "btfracture_test_statistics";
    std::filesystem::create_directories(dir);
    return dir / name;
}

std::vector<std::string> linesOf(const std::filesystem::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Uniform in (0, 1], from the raw 64-bit engine (std::uniform_real_distribution differs between
// standard libraries).
double uniform(std::mt19937_64& engine) {
    return (static_cast<double>(engine() >> 11) + 1.0) * 0x1.0p-53;
}

// Inverse transform: (zeta V)^(1/3) = -ln u is exponential with mean 1.
std::vector<double> mottSample(size_t n, double mean, std::uint64_t seed) {
    std::mt19937_64 engine(seed);
    std::vector<double> v(n);
    for (double& x : v) {
        const double e = -std::log(uniform(engine));
        x = e * e * e * mean / 6.0;
    }
    return v;
}

}  // namespace

// P(V) = exp(-(zeta V)^(1/3)) with zeta = 6 / mean: P(0) = 1, P(mean) = exp(-6^(1/3)), the median
// is (ln 2)^3 / zeta, and the mean of the distribution, the integral of P over [0, inf), is 6 / zeta.
TEST(Mott, SurvivalFunctionMatchesItsAnalyticProperties) {
    const double mean = 0.02, zeta = 6.0 / mean;
    EXPECT_DOUBLE_EQ(mottSurvival(0.0, mean), 1.0);
    EXPECT_NEAR(mottSurvival(mean, mean), std::exp(-std::cbrt(6.0)), 1e-15);
    EXPECT_NEAR(mottSurvival(std::pow(std::log(2.0), 3) / zeta, mean), 0.5, 1e-14);
    // Integral in x = (zeta V)^(1/3): V = x^3 / zeta, dV = 3 x^2 / zeta dx; Simpson on [0, 60].
    const int n = 20000;
    const double h = 60.0 / n;
    double integral = 0.0;
    for (int i = 0; i <= n; ++i) {
        const double x = i * h, weight = i == 0 || i == n ? 1.0 : i % 2 ? 4.0 : 2.0;
        integral += weight * mottSurvival(x * x * x / zeta, mean) * 3.0 * x * x / zeta;
    }
    integral *= h / 3.0;
    EXPECT_NEAR(integral / mean, 1.0, 1e-9);
    EXPECT_THROW(mottSurvival(1.0, 0.0), Error);
}

// 4000 volumes drawn from Mott's law match it: Kolmogorov-Smirnov distance below 0.03 (the 95 %
// critical value is 1.36 / sqrt(n) = 0.0215 for a fully specified law; estimating the mean from
// the sample only lowers it), and every well-filled bin holds its expected count within 5 sigma.
// Uniformly distributed volumes are rejected (distance > 0.1).
TEST(Mott, SamplesFromMottsLawMatchAndOthersDoNot) {
    const std::vector<double> sample = mottSample(4000, 0.01, 7);
    const MottComparison c = compareWithMott(sample, 4);
    EXPECT_LT(c.ksDistance, 0.03);
    EXPECT_NEAR(c.mean, 0.01, 0.01 * 0.1);  // the sample mean, within 10 %
    int total = 0;
    double expected = 0.0;
    for (const MottBin& b : c.bins) {
        total += b.count;
        expected += b.expected;
        EXPECT_NEAR(b.upper / b.lower, std::pow(10.0, 0.25), 1e-12);
        if (b.expected > 20) {
            EXPECT_NEAR(b.count, b.expected, 5.0 * std::sqrt(b.expected)) << b.lower;
        }
    }
    EXPECT_EQ(total, 4000);
    EXPECT_NEAR(expected, 4000.0, 4000.0 * 0.01);  // the bins cover nearly all of the law's mass
    EXPECT_LE(c.bins.front().lower, c.volumes.front());
    EXPECT_GT(c.bins.back().upper, c.volumes.back());

    std::vector<double> uniformVolumes;
    for (int i = 1; i <= 4000; ++i) uniformVolumes.push_back(i * 0.02 / 4000.0);
    EXPECT_GT(compareWithMott(uniformVolumes).ksDistance, 0.1);
}

TEST(Mott, Csv) {
    const MottComparison c = compareWithMott(mottSample(300, 0.05, 11), 2);
    const auto csv = scratch("mott.csv");
    writeMottCsv(csv.string(), c);
    const auto lines = linesOf(csv);
    ASSERT_EQ(lines.size(), c.bins.size() + 1);
    EXPECT_EQ(lines[0], "bin_lower,bin_upper,count,mott_expected,survival_fragments,survival_mott");
    // The first bin's lower edge lies below every volume: both survival functions are ~1 there.
    double lower, upper, count, mott, fragments, survival;
    char comma;
    std::istringstream(lines[1]) >> lower >> comma >> upper >> comma >> count >> comma >> mott >> comma >>
        fragments >> comma >> survival;
    EXPECT_DOUBLE_EQ(fragments, 1.0);
    EXPECT_GT(survival, 0.9);
    EXPECT_THROW(compareWithMott({}), Error);
    EXPECT_THROW(compareWithMott({0.1, -1.0}), Error);
}

TEST(StatisticsCsv, RowsColumnsAndQuoting) {
    const auto path = scratch("statistics.csv");
    {
        StatisticsCsv csv(path.string());
        FractureEventRecord r;
        r.step = 120;
        r.time = 0.48;
        r.body = "bunny";
        r.contacts = 3;
        r.impulse = 12.5;
        r.contactDuration = 2.5e-4;
        r.method = FractureMethod::Estimated;
        r.bemTriangles = 800;
        r.crackTriangles = 212;
        r.fragments = {"bunny_f1", "bunny_f2"};
        r.fractureSeconds = 1.25;
        r.swapSeconds = 0.01;
        csv.add(r);
        r.body = "odd, \"name\"";
        r.fragments = {};
        r.hasEnergy = true;
        r.energy.bodyKinetic = 2.0;
        r.energy.partnersKinetic = 6.0;
        r.energy.swapKinetic = 2.0;
        r.energy.separatedKinetic = 1.5;
        r.energy.swapPotentialGain = 0.25;
        r.energy.separatedPotentialGain = 0.5;
        r.energy.replayKinetic = 3.0;
        r.energy.followingKinetic = 3.25;
        r.energy.followingSteps = 20;
        r.energy.worldBefore = 100.0;
        r.energy.worldGain = -0.5;
        csv.add(r);
        EXPECT_EQ(csv.rows(), 2);
        csv.close();
    }
    const auto lines = linesOf(path);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(
        lines[0],
        "event,step,time_s,body,contacts,impulse_Ns,contact_duration_s,method,bem_triangles,crack_triangles,"
        "fragments,fragment_names,fracture_wall_s,swap_wall_s,ke_body_J,ke_partners_J,ke_swap_J,ke_separated_"
        "J,"
        "pe_gain_swap_J,pe_gain_separated_J,ke_replay_J,ke_following_max_J,following_steps,world_energy_"
        "before_J,world_energy_gain_J,"
        "energy_added_fraction");
    EXPECT_EQ(lines[1],
              "1,120,0.48,bunny,3,12.5,0.00025,est,800,212,2,bunny_f1 bunny_f2,1.25,0.01,,,,,,,,,,,,");
    EXPECT_EQ(lines[2],
              "2,120,0.48,\"odd, "
              "\"\"name\"\"\",3,12.5,0.00025,est,800,212,0,,1.25,0.01,2,6,2,1.5,0.25,0.5,3,3.25,20,100,-0.5,"
              "-0.0625");
    EXPECT_THROW(StatisticsCsv("/no/such/folder/s.csv"), Error);
}

// A statistics row waits for its event's energy audit; rows keep the event order whatever order
// the audits arrive in.
TEST(FractureRecorder, RowsWaitForTheirEnergyAuditInEventOrder) {
    const auto csv = scratch("recorder_audits.csv");
    FractureRecorder recorder(csv.string());
    recorder.addOriginal("a", 1.0);
    recorder.addOriginal("b", 1.0);
    FractureEventRecord event;
    event.worldEvent = 7;
    event.body = "a";
    recorder.record(event, {0.5, 0.5});
    event.worldEvent = 8;
    event.body = "b";
    recorder.record(event, {0.25, 0.75});
    FractureEnergyAudit audit;
    audit.event = 8;
    audit.bodyKinetic = 4.0;
    recorder.addEnergyAudit(audit);
    EXPECT_EQ(linesOf(csv).size(), 1u);  // event 7 still waits, and 8 behind it
    audit.event = 7;
    audit.bodyKinetic = 2.0;
    recorder.addEnergyAudit(audit);
    const auto lines = linesOf(csv);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[1].substr(0, 4), "1,0,");
    EXPECT_NE(lines[1].find(",a,"), std::string::npos);
    EXPECT_NE(lines[1].find(",2,0,0,0,0,0,"), std::string::npos) << lines[1];
    EXPECT_NE(lines[2].find(",b,"), std::string::npos);
    EXPECT_NE(lines[2].find(",4,0,0,0,0,0,"), std::string::npos) << lines[2];
    recorder.close();
}

// Fragments are named <original>_f<k> in creation order, per original; a fragment that breaks
// again leaves the list; relative volumes refer to the original.
TEST(FractureRecorder, NamesAndVolumeBookkeeping) {
    const auto csv = scratch("recorder.csv");
    FractureRecorder recorder(csv.string());
    recorder.addOriginal("bunny", 2.0);
    recorder.addOriginal("column", 10.0);
    FractureEventRecord event;
    event.body = "bunny";
    EXPECT_EQ(recorder.record(event, {1.0, 0.6, 0.4}),
              (std::vector<std::string>{"bunny_f1", "bunny_f2", "bunny_f3"}));
    event.body = "column";
    EXPECT_EQ(recorder.record(event, {9.0, 1.0}), (std::vector<std::string>{"column_f1", "column_f2"}));
    event.body = "bunny_f2";
    EXPECT_EQ(recorder.record(event, {0.5, 0.1}), (std::vector<std::string>{"bunny_f4", "bunny_f5"}));
    EXPECT_EQ(recorder.events(), 3);

    const auto pieces = recorder.fragments();
    std::vector<std::string> names;
    double bunnyVolume = 0.0;
    for (const auto& f : pieces) {
        names.push_back(f.name);
        if (f.original == "bunny") bunnyVolume += f.relativeVolume;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"bunny_f1", "bunny_f3", "column_f1", "column_f2", "bunny_f4",
                                               "bunny_f5"}));
    EXPECT_NEAR(bunnyVolume, 1.0, 1e-15);  // the pieces add up to the original
    EXPECT_EQ(pieces[4].generation, 2);
    EXPECT_DOUBLE_EQ(pieces[5].relativeVolume, 0.05);

    event.body = "bunny_f2";
    EXPECT_THROW(recorder.record(event, {0.1}), Error);  // already broken
    event.body = "teapot";
    EXPECT_THROW(recorder.record(event, {0.1}), Error);  // unknown
    event.body = "column_f1";
    EXPECT_THROW(recorder.record(event, {0.0}), Error);  // zero volume

    const auto histogram = scratch("fragment_volumes.csv");
    ASSERT_TRUE(recorder.writeFragmentVolumes(histogram.string(), scratch("fragments.csv").string()));
    EXPECT_EQ(linesOf(scratch("fragments.csv")).size(), 7u);
    EXPECT_EQ(linesOf(scratch("fragments.csv"))[5], "bunny_f4,bunny,2,0.5,0.25");
    EXPECT_EQ(linesOf(histogram)[0],
              "bin_lower,bin_upper,count,mott_expected,survival_fragments,survival_mott");
    recorder.close();
    EXPECT_EQ(linesOf(csv).size(), 4u);  // rows without an energy audit are written at close

    FractureRecorder none;
    none.addOriginal("pane", 1.0);
    EXPECT_FALSE(
        none.writeFragmentVolumes(scratch("none_volumes.csv").string(), scratch("none.csv").string()));
}
