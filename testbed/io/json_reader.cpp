#include "testbed/io/json_reader.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "testbed/core/error.h"
#include "testbed/io/json_input.h"

namespace testbed {
namespace {

using nlohmann::json;

std::string join(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ", ") + name;
  return text;
}

std::string range(std::int64_t lo, std::int64_t hi) {
  return "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}

// The whole value of a number, or none for a fraction or a value no int64 holds. Parsed
// integers are taken exactly; a float (3.0) by its value, so 3.0 reads as 3.
std::optional<std::int64_t> wholeValue(const json& value) {
  if (value.is_number_unsigned()) {
    const auto v = value.get<std::uint64_t>();
    if (v > std::uint64_t(std::numeric_limits<std::int64_t>::max())) return std::nullopt;
    return std::int64_t(v);
  }
  if (value.is_number_integer()) return value.get<std::int64_t>();
  const double x = value.get<double>();
  // 2^63 itself is not representable as int64; the bounds are exact doubles.
  if (!std::isfinite(x) || x != std::floor(x) || x < -9.2233720368547758e18 || x >= 9.2233720368547758e18)
    return std::nullopt;
  return std::int64_t(x);
}

}  // namespace

JsonField::JsonField(const nlohmann::json& value, std::string file, std::string path)
    : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

void JsonField::fail(const std::string& problem) const {
  std::string where = file_;
  if (!path_.empty()) where += (where.empty() ? "" : ": ") + path_;
  throw InputError(where.empty() ? problem : where + ": " + problem);
}

void JsonField::failAt(std::string_view key, const std::string& problem) const {
  JsonField(*value_, file_, keyPath(path_, std::string(key))).fail(problem);
}

std::string JsonField::brief() const { return briefJson(*value_); }

const JsonField& JsonField::object() const {
  if (!value_->is_object()) fail("expected a JSON object {...}, got " + brief());
  return *this;
}

bool JsonField::has(std::string_view key) const { return value_->is_object() && value_->contains(key); }

std::optional<JsonField> JsonField::find(std::string_view key) const {
  object();
  const auto it = value_->find(key);
  if (it == value_->end()) return std::nullopt;
  return JsonField(*it, file_, keyPath(path_, std::string(key)));
}

JsonField JsonField::operator[](std::string_view key) const {
  std::optional<JsonField> found = find(key);
  if (!found) failAt(key, "missing required key");
  return *found;
}

void JsonField::allowKeys(const std::vector<std::string>& allowed) const {
  object();
  for (const auto& [name, value] : value_->items())
    if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
      failAt(name, "unknown key (allowed here: " + join(allowed) + ")");
}

std::vector<std::string> JsonField::keys() const {
  object();
  std::vector<std::string> out;
  for (const auto& [name, value] : value_->items()) out.push_back(name);
  return out;
}

std::size_t JsonField::arraySize(const std::string& form) const {
  if (!value_->is_array()) fail("expected " + form + ", got " + brief());
  return value_->size();
}

void JsonField::arrayOf(std::size_t n, const std::string& form) const {
  if (!value_->is_array() || value_->size() != n) fail("expected " + form + ", got " + brief());
}

JsonField JsonField::operator[](std::size_t index) const {
  arraySize();
  if (index >= value_->size()) fail("expected at least " + std::to_string(index + 1) + " elements, got " + brief());
  return JsonField((*value_)[index], file_, indexPath(path_, index));
}

std::string JsonField::text() const {
  if (!value_->is_string()) fail("expected a string, got " + brief());
  return value_->get<std::string>();
}

bool JsonField::boolean() const {
  if (!value_->is_boolean()) fail("expected true or false, got " + brief());
  return value_->get<bool>();
}

double JsonField::number() const {
  if (!value_->is_number()) fail("expected a number, got " + brief());
  const double x = value_->get<double>();
  if (!std::isfinite(x)) fail("not a finite number");
  return x;
}

std::int64_t JsonField::whole(std::int64_t lo, std::int64_t hi) const {
  const std::optional<std::int64_t> v = value_->is_number() ? wholeValue(*value_) : std::nullopt;
  // A whole number beyond int64 is out of every range a reader asks for.
  const bool huge = value_->is_number() && !v && std::isfinite(value_->get<double>()) &&
                    value_->get<double>() == std::floor(value_->get<double>());
  if (!v && !huge) fail("expected " + range(lo, hi) + ", got " + brief());
  if (huge || *v < lo || *v > hi) fail("must be " + range(lo, hi) + ", got " + brief());
  return *v;
}

std::uint64_t JsonField::count() const {
  const std::optional<std::int64_t> v = value_->is_number() ? wholeValue(*value_) : std::nullopt;
  if (!v || *v < 0) fail("expected a non-negative integer, got " + brief());
  return std::uint64_t(*v);
}

std::size_t JsonField::word(std::initializer_list<std::string_view> words) const {
  if (value_->is_string()) {
    const std::string& given = value_->get_ref<const std::string&>();
    for (std::size_t i = 0; i < words.size(); ++i)
      if (words.begin()[i] == given) return i;
  }
  fail("expected " + quotedAlternatives(words) + ", got " + brief());
}

std::string quotedAlternatives(std::initializer_list<std::string_view> words) {
  std::string text;
  for (std::size_t i = 0; i < words.size(); ++i) {
    if (i > 0) text += i + 1 == words.size() ? " or " : ", ";
    text += nlohmann::json(std::string(words.begin()[i])).dump();
  }
  return text;
}

}  // namespace testbed
