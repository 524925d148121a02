// A plugin whose citation and summary hold line breaks, '#', '|', backticks and HTML, for
// tests/recorded_command_test.cpp: `testbed list` keeps one line per fact and `list
// --markdown` one table row per technique. Never rendered.
#include "testbed/technique/plugin.h"

namespace {

using namespace testbed;

class Silent final : public ShadowTechnique {
 public:
  void configure(const ParameterSet&) override {}
  void render(const FrameInputs&, PassTimer&, const VisibilityTarget&) override {}
};

}  // namespace

TESTBED_PLUGIN(registrar) {
  registrar.add<Silent>({.id = "hostile-text",
                         .output = OutputKind::Hard,
                         .citation = "Cite\n# heading | cell `code` <script>alert(1)</script>",
                         .summary = "one\ntwo\r\n# three",
                         .passes = {{.name = "nothing", .paperStep = "a fixture that draws nothing"}}});
}
