#pragma once
// The one checked reader of JSON values the testbed reads: scene files, sweep specs and
// the overrides in a sweep.json, records (records.json, metrics.json, T.json). Every
// reader takes its values through a JsonField, so every file obeys the same rules and
// every fault is one InputError line "<file>: <key path>: <problem>", e.g.
//   scenes/x.json: objects[2].translate: expected [x, y, z], got [1,2]
// (the file or the path left out where empty). The rules:
//   - Whole numbers: a number is whole when its value is, however it is written: 3, 3.0
//     and 3e0 are all 3; 3.5 is refused. JSON has one number type, and tools such as
//     Python's json or a spreadsheet write 3.0 for a computed 3.
//   - Numbers are finite. A parsed file cannot hold NaN or infinity (json_input.h refuses
//     1e999), but a value built in code can; both are refused the same way.
//   - Strings, booleans, arrays and objects are what they say; nothing converts.
//   - Arrays of a fixed length (a vec3) are refused at any other length.
//   - Enum words are one of a listed set of strings, case and all.
//   - Unknown keys are refused where the reader lists the keys an object may hold
//     (allowKeys): a typo must not fall back to a default silently.
// The file itself is read by json_input.h (size cap, strict syntax, no duplicate keys).
#include <array>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace testbed {

// A value in a JSON document and where it is: the file and the key path to it.
class JsonField {
 public:
  // `file` names the document in messages (a path, or "records.json: [3]"-like text);
  // `path` is the key path of `value` in it ("" for the top level).
  JsonField(const nlohmann::json& value, std::string file, std::string path = {});

  const nlohmann::json& json() const { return *value_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  // "<file>: <path>: <problem>" as an InputError.
  [[noreturn]] void fail(const std::string& problem) const;
  // The same, for a key of this object that may be absent (a missing key's message).
  [[noreturn]] void failAt(std::string_view key, const std::string& problem) const;

  // ---- Objects ----
  // Fails unless this is an object: "expected a JSON object {...}, got <value>".
  const JsonField& object() const;
  bool has(std::string_view key) const;  // false for a non-object
  // The value at a required key: "missing required key" where absent.
  JsonField operator[](std::string_view key) const;
  std::optional<JsonField> find(std::string_view key) const;
  // Refuses any key not in `allowed`: "<path>.<key>: unknown key (allowed here: a, b)".
  void allowKeys(const std::vector<std::string>& allowed) const;
  // The object's keys, in the document's order.
  std::vector<std::string> keys() const;

  // ---- Arrays ----
  // Fails unless this is an array (of `n` elements where given): "expected <form>, got …".
  std::size_t arraySize(const std::string& form = "an array") const;
  void arrayOf(std::size_t n, const std::string& form) const;
  JsonField operator[](std::size_t index) const;

  // ---- Values ----
  std::string text() const;    // a string
  bool boolean() const;        // true or false
  double number() const;       // a finite number
  // A whole number in [lo, hi] (the rule above): "expected an integer in [lo, hi], got
  // 3.5" for a fraction, "must be an integer in [lo, hi], got 7" out of range.
  std::int64_t whole(std::int64_t lo, std::int64_t hi) const;
  int integer(int lo, int hi) const { return int(whole(lo, hi)); }
  // A whole number >= 0 (counts, sizes in bytes): "expected a non-negative integer, got …".
  std::uint64_t count() const;
  // N finite numbers: "expected an array of N numbers, got …".
  template <std::size_t N>
  std::array<double, N> numbers() const {
    arrayOf(N, "an array of " + std::to_string(N) + " numbers");
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = (*this)[i].number();
    return out;
  }
  // The index of the string in `words`: "expected "a", "b" or "c", got "d"".
  std::size_t word(std::initializer_list<std::string_view> words) const;

  // A value for "got ...": one short line (json_input.h briefJson).
  std::string brief() const;

 private:
  const nlohmann::json* value_;
  std::string file_, path_;
};

// "a, b or c" of the words, each quoted as JSON: the list in word()'s message.
std::string quotedAlternatives(std::initializer_list<std::string_view> words);

}  // namespace testbed
