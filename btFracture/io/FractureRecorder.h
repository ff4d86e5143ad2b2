// SPDX-License-Identifier: Zlib
#pragma once
// What a run records about fracture: the fragments' names and volumes (a ledger of every body
// that came from breaking an original scene body), the statistics CSV, and at the end the
// fragment-volume histogram against Mott's distribution.
//
// The fracture world's listener calls record() once per event; nothing else needs to know how
// fragments are named or where the statistics go.
#include <btFracture/io/StatisticsCsv.h>

#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace btfracture {

class FractureRecorder {
public:
    // `statisticsCsv`: path of the statistics CSV, or empty for none; `wallTimes` false leaves its
    // wall-time columns empty (StatisticsCsv).
    explicit FractureRecorder(const std::string& statisticsCsv = "", bool wallTimes = true);

    // A scene body that may break, with its volume [m^3].
    void addOriginal(const std::string& name, double volume);

    // One fracture event: `record.body` (an original or an earlier fragment) broke into pieces of
    // `fragmentVolumes` [m^3]. Names the pieces "<original>_f<k>", k counting from 1 per original
    // body in creation order (so names are stable from frame to frame and run to run), fills
    // record.fragments with them and returns the names. The CSV row is written once the event's
    // energy audit arrived (addEnergyAudit), rows in event order. Throws btfracture::Error for an
    // unknown body or a non-positive volume.
    std::vector<std::string> record(FractureEventRecord record, const std::vector<double>& fragmentVolumes);
    // The energy audit of the recorded event with worldEvent == audit.event (others are ignored).
    void addEnergyAudit(const FractureEnergyAudit& audit);

    struct Fragment {
        std::string name, original;
        double volume = 0.0;          // [m^3]
        double relativeVolume = 0.0;  // volume / the original's volume
        int generation = 1;           // 1: broke off the original, 2: off a generation-1 fragment, ...
    };
    // Fragments that have not broken again, in creation order.
    std::vector<Fragment> fragments() const;

    int events() const { return events_; }

    // Writes `histogramCsv` with the current fragments' relative volumes against Mott's
    // distribution (io/MottHistogram.h), and `fragmentsCsv` listing them
    // (name,original,generation,volume_m3,relative_volume). Returns false, writing nothing, when
    // there are no fragments.
    bool writeFragmentVolumes(const std::string& histogramCsv, const std::string& fragmentsCsv) const;

    // Writes the rows still waiting for their audits (energy columns empty) and closes the
    // statistics CSV (throws Error naming the path when writing failed).
    void close();

private:
    struct Piece {
        std::string original;
        double volume = 0.0;
        int generation = 0;
        bool broken = false;
        size_t order = 0;  // creation order
    };
    void writeAudited();  // the leading pending rows that have their energy audit

    std::unique_ptr<StatisticsCsv> csv_;
    std::deque<FractureEventRecord> pending_;  // rows waiting for their audit, event order
    std::map<std::string, Piece> pieces_;      // originals and fragments by name
    std::map<std::string, double> originals_;  // original volumes
    std::map<std::string, int> nextIndex_;     // per original: k of its next fragment
    size_t created_ = 0;
    int events_ = 0;
};

}  // namespace btfracture
