#pragma once
// JSON files the testbed reads (scene files, sweep specs, a shard's sweep.json, spec.json
// and records.json, metrics.json): read with the size cap of input_file.h (regular files
// only) and parsed strictly, every fault one InputError line naming the file and,
// where there is one, the key path ("objects[1].scale"):
//   - syntax errors with line and column;
//   - numbers a double cannot hold (1e999), which nlohmann refuses before there is a value;
//   - a key given twice in one object (nlohmann would keep the last silently);
//   - nesting deeper than kMaxJsonDepth (no input needs it, and printing or walking such a
//     value recursively would overflow the stack).
// The values in a parsed document are then read through json_reader.h, whose rules (whole
// numbers, finite numbers, unknown keys) every reader shares.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "testbed/io/input_file.h"

namespace testbed {

inline constexpr int kMaxJsonDepth = 64;

nlohmann::json readJsonInput(const std::filesystem::path& file, std::uint64_t maxBytes = kMaxJsonInputBytes);
// The same on text already read; `file` names it in messages.
nlohmann::json parseJsonInput(const std::string& text, const std::filesystem::path& file);

// Key paths as messages print them: "camera" / "eye" → "camera.eye", then [1] →
// "camera.eye[1]"; a key that is not a plain word is quoted in brackets: ["a b"].
std::string keyPath(const std::string& path, const std::string& key);
std::string indexPath(const std::string& path, std::size_t index);

// A value for "got ...": at most ~40 characters on one line, without printing (or
// recursing into) more of a large or deep value than that.
std::string briefJson(const nlohmann::json& value);

}  // namespace testbed
