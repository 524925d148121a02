#include "testbed/technique/parameter_binder.h"

namespace testbed {

ParameterBinder& ParameterBinder::boolean(std::string_view name, bool& member, bool value, std::string_view help) {
  if (specs_) declare(ParameterSpec::boolean(std::string(name), value, std::string(help)));
  member = specs_ ? value : values_->getBool(name);
  return *this;
}

ParameterBinder& ParameterBinder::choice(std::string_view name, std::string& member, std::string value,
                                         std::vector<std::string> choices, std::string_view help) {
  if (specs_) {
    member = value;
    declare(ParameterSpec::choice(std::string(name), std::move(value), std::move(choices), std::string(help)));
  } else {
    member = values_->getChoice(name);
  }
  return *this;
}

ParameterBinder& ParameterBinder::oddOnly() {
  if (specs_) {
    if (specs_->empty()) throw std::logic_error("oddOnly() before any parameter");
    specs_->back().oddOnly = true;
  }
  return *this;
}

}  // namespace testbed
