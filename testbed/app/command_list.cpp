// `testbed list [--json]`: every registered technique with its parameters.
#include <iostream>

#include <nlohmann/json.hpp>

#include "testbed/app/commands.h"
#include "testbed/app/plugins.h"
#include "testbed/core/messages.h"

namespace testbed {
namespace {

nlohmann::json specJson(const ParameterSpec& spec) {
  nlohmann::json j{{"name", spec.name}, {"type", typeName(spec.type)}, {"help", spec.help}};
  std::visit([&](const auto& v) { j["default"] = v; }, spec.defaultValue);
  if (spec.type == ParameterType::Int || spec.type == ParameterType::Float) {
    j["min"] = spec.min;
    j["max"] = spec.max;
  }
  if (spec.type == ParameterType::Choice) j["choices"] = spec.choices;
  if (spec.oddOnly) j["odd_only"] = true;
  return j;
}

}  // namespace

CommandRunner addListCommand(CLI::App& app) {
  auto* command = app.add_subcommand("list", "list the techniques and their parameters");
  auto json = std::make_shared<bool>(false);
  auto markdown = std::make_shared<bool>(false);
  command->add_flag("--json", *json, "print JSON");
  command->add_flag("--markdown", *markdown, "print the README's technique table");
  auto plugins = std::make_shared<std::vector<std::string>>();
  addPluginOption(*command, *plugins);
  return {command, [json, markdown, plugins]() {
    loadPlugins(*plugins);
    const auto techniques = registeredTechniques();
    if (*markdown) {
      std::cout << techniqueTableMarkdown();
      return 0;
    }
    if (*json) {
      nlohmann::json all = nlohmann::json::array();
      for (const auto& t : techniques) {
        nlohmann::json parameters = nlohmann::json::array();
        for (const auto& spec : t.info->parameters) parameters.push_back(specJson(spec));
        all.push_back({{"id", t.info->id},
                       {"family", t.info->family},
                       {"output", t.info->output == OutputKind::Hard ? "hard" : "filtered"},
                       {"citation", t.info->citation},
                       {"summary", t.info->summary},
                       {"parameters", parameters}});
      }
      std::cout << all.dump(2) << "\n";
      return 0;
    }
    // One line per fact: a plugin's text with a line break or control character in it
    // must not start a line of its own (oneLine).
    for (const auto& t : techniques) {
      std::cout << t.info->id << "  [" << oneLine(t.info->family) << ", "
                << (t.info->output == OutputKind::Hard ? "hard" : "filtered") << "]  " << oneLine(t.info->summary)
                << "\n    " << oneLine(t.info->citation) << "\n";
      for (const auto& spec : t.info->parameters)
        std::cout << "    --set " << spec.name << "=" << oneLine(formatValue(spec.defaultValue)) << "  ("
                  << typeName(spec.type) << ") " << oneLine(spec.help) << "\n";
    }
    return 0;
  }};
}

}  // namespace testbed
