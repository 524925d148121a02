#include "testbed/io/json_input.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <vector>

#include "testbed/core/error.h"
#include "testbed/io/input_file.h"

namespace testbed {
namespace {

using nlohmann::json;

constexpr std::size_t kBrief = 40;

// A string quoted as JSON, cut first so that a megabyte string is not copied to show 40.
std::string quoted(const std::string& text) {
  return json(text.substr(0, kBrief)).dump(-1, ' ', false, json::error_handler_t::replace);
}

// Appends a brief form of `value` to `out` until `out` reaches kBrief characters.
void appendBrief(const json& value, std::string& out, int depth) {
  if (out.size() >= kBrief) return;
  if (!value.is_structured()) {
    out += value.is_string() ? quoted(value.get_ref<const std::string&>()) : value.dump();
    return;
  }
  const bool array = value.is_array();
  out += array ? '[' : '{';
  if (depth >= 4 && !value.empty()) out += "...";
  bool first = true;
  for (auto it = value.begin(); depth < 4 && it != value.end() && out.size() < kBrief; ++it) {
    if (!first) out += ',';
    first = false;
    if (!array) out += quoted(it.key()) + ':';
    appendBrief(*it, out, depth + 1);
  }
  out += array ? ']' : '}';
}

// Where the parser is, for messages: one frame per open array or object.
struct Frame {
  bool array = false;
  std::string key;          // objects: the key being read
  std::size_t elements = 0;  // arrays: elements started so far
  std::set<std::string> keys;
};

// The key path of the value being read. Outer arrays have counted the element that holds
// it; the innermost array has not yet counted a value that failed to parse.
std::string pathOf(const std::vector<Frame>& frames) {
  std::string path;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const Frame& f = frames[i];
    if (!f.array) path = keyPath(path, f.key);
    else path = indexPath(path, i + 1 == frames.size() ? f.elements : f.elements - 1);
  }
  return path;
}

// "[json.exception.parse_error.101] parse error at line 3, column 5: <detail>" →
// "line 3, column 5: JSON syntax error: <detail>", kept short.
std::string syntaxMessage(const std::string& what) {
  const auto at = what.find("line ");
  const auto colon = what.find(": ", at == std::string::npos ? 0 : at);
  std::string where = "JSON syntax error", detail = what;
  if (at != std::string::npos && colon != std::string::npos) {
    where = what.substr(at, colon - at) + ": JSON syntax error";
    detail = what.substr(colon + 2);
  }
  if (detail.size() > 160) detail = detail.substr(0, 157) + "...";
  return where + ": " + detail;
}

}  // namespace

std::string keyPath(const std::string& path, const std::string& key) {
  const bool plain = !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
  if (!plain) return path + "[" + briefJson(json(key)) + "]";
  return path.empty() ? key : path + "." + key;
}

std::string indexPath(const std::string& path, std::size_t index) { return path + "[" + std::to_string(index) + "]"; }

std::string briefJson(const json& value) {
  std::string text;
  appendBrief(value, text, 0);
  if (text.size() > kBrief) text = text.substr(0, kBrief - 3) + "...";
  return text;
}

json readJsonInput(const std::filesystem::path& file, std::uint64_t maxBytes) {
  return parseJsonInput(readInputFile(file, maxBytes), file);
}

json parseJsonInput(const std::string& text, const std::filesystem::path& file) {
  const std::string name = file.string();
  std::vector<Frame> frames;
  const json::parser_callback_t track = [&](int depth, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    const bool opens = event == E::object_start || event == E::array_start;
    if (opens && depth >= kMaxJsonDepth)
      throw InputError(name + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    if (!frames.empty() && frames.back().array && (opens || event == E::value)) ++frames.back().elements;
    if (opens) frames.push_back({event == E::array_start, {}, 0, {}});
    if (event == E::object_end || event == E::array_end) frames.pop_back();
    if (event == E::key) {
      Frame& object = frames.back();
      object.key = parsed.get<std::string>();
      if (!object.keys.insert(object.key).second)
        throw InputError(name + ": " + pathOf(frames) + ": key given twice in one object");
    }
    return true;
  };
  try {
    return json::parse(text, track);
  } catch (const json::out_of_range&) {
    // A number overflowing a double (1e999): the value being read when it threw.
    const std::string path = pathOf(frames);
    throw InputError(name + ": " + (path.empty() ? "" : path + ": ") + "not a finite number");
  } catch (const json::exception& e) {
    throw InputError(name + ": " + syntaxMessage(e.what()));
  }
}

}  // namespace testbed
