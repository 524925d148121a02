#pragma once
// report.md of `compare --frames`: one row per technique with its temporal figures (flicker,
// crawl, crawl missed) and, for every report column the metric table stores, the mean,
// p95 and max over frames, all read from the sequence records (harness/sequence.h).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace testbed {

std::string sequenceMarkdown(const std::string& scene, const std::vector<nlohmann::json>& sequenceRecords);

}  // namespace testbed
