// SPDX-License-Identifier: Zlib
#include <btFracture/io/FractureRecorder.h>

#include <btFracture/core/Error.h>
#include <btFracture/io/MottHistogram.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace btfracture {

FractureRecorder::FractureRecorder(const std::string& statisticsCsv, bool wallTimes) {
    if (!statisticsCsv.empty()) csv_ = std::make_unique<StatisticsCsv>(statisticsCsv, wallTimes);
}

void FractureRecorder::addOriginal(const std::string& name, double volume) {
    if (!(volume > 0.0) || !std::isfinite(volume))
        throw Error("FractureRecorder: body '" + name + "' has volume " + std::to_string(volume) +
                    "; a breakable body needs a positive volume");
    if (!pieces_.emplace(name, Piece{name, volume, 0, false, created_++}).second)
        throw Error("FractureRecorder: body '" + name + "' added twice");
    originals_[name] = volume;
}

std::vector<std::string> FractureRecorder::record(FractureEventRecord record,
                                                  const std::vector<double>& volumes) {
    const auto parent = pieces_.find(record.body);
    if (parent == pieces_.end())
        throw Error("FractureRecorder: fracture event on unknown body '" + record.body + "'");
    if (parent->second.broken)
        throw Error("FractureRecorder: body '" + record.body +
                    "' already broke and is no longer in the world");
    for (double v : volumes)
        if (!(v > 0.0) || !std::isfinite(v))
            throw Error("FractureRecorder: a fragment of '" + record.body + "' has volume " +
                        std::to_string(v));
    const Piece parentPiece = parent->second;
    parent->second.broken = true;
    record.fragments.clear();
    for (double v : volumes) {
        const std::string name =
            parentPiece.original + "_f" + std::to_string(++nextIndex_[parentPiece.original]);
        pieces_[name] = Piece{parentPiece.original, v, parentPiece.generation + 1, false, created_++};
        record.fragments.push_back(name);
    }
    ++events_;
    std::vector<std::string> names = record.fragments;
    if (csv_) pending_.push_back(std::move(record));
    return names;
}

void FractureRecorder::addEnergyAudit(const FractureEnergyAudit& audit) {
    for (FractureEventRecord& row : pending_)
        if (row.worldEvent == audit.event) {
            row.hasEnergy = true;
            row.energy = audit;
        }
    writeAudited();
}

void FractureRecorder::writeAudited() {
    while (!pending_.empty() && pending_.front().hasEnergy) {
        csv_->add(pending_.front());
        pending_.pop_front();
    }
}

std::vector<FractureRecorder::Fragment> FractureRecorder::fragments() const {
    std::vector<std::pair<size_t, Fragment>> ordered;
    for (const auto& [name, piece] : pieces_) {
        if (piece.generation == 0 || piece.broken) continue;
        ordered.push_back(
            {piece.order, Fragment{name, piece.original, piece.volume,
                                   piece.volume / originals_.at(piece.original), piece.generation}});
    }
    std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Fragment> result;
    for (auto& item : ordered) result.push_back(std::move(item.second));
    return result;
}

bool FractureRecorder::writeFragmentVolumes(const std::string& histogramCsv,
                                            const std::string& fragmentsCsv) const {
    const std::vector<Fragment> pieces = fragments();
    if (pieces.empty()) return false;
    std::ofstream out(fragmentsCsv, std::ios::binary | std::ios::trunc);
    if (!out) throw Error("cannot create fragment list '" + fragmentsCsv + "'");
    out << "name,original,generation,volume_m3,relative_volume\n";
    std::vector<double> relative;
    for (const Fragment& f : pieces) {
        char numbers[96];
        std::snprintf(numbers, sizeof numbers, "%d,%.9g,%.9g\n", f.generation, f.volume, f.relativeVolume);
        out << csvField(f.name) << ',' << csvField(f.original) << ',' << numbers;
        relative.push_back(f.relativeVolume);
    }
    out.close();
    if (out.fail()) throw Error("writing fragment list '" + fragmentsCsv + "' failed");
    const MottComparison comparison = compareWithMott(relative);
    writeMottCsv(histogramCsv, comparison);
    return true;
}

void FractureRecorder::close() {
    if (!csv_) return;
    for (const FractureEventRecord& row : pending_) csv_->add(row);
    pending_.clear();
    csv_->close();
}

}  // namespace btfracture
