#pragma once
// The texture units, image units and shader-storage binding points of units.glsl, the one
// table of them, for C++: each as a constant (`glBindTextureUnit(kShadowMapTextureUnit, …)`)
// and all of them as kUnits, for tests/units_test.cpp's collision check.
#include <string_view>

namespace testbed {

enum class UnitKind { Texture, Image, Buffer };
// Which programs bind a unit together (units.glsl).
enum class UnitScope { Shared, Rpcf, Smsr2Pass, SilhouetteMap, Prefiltered, Edtsm, BandedEdt, GroundTruth, Shading, Probe,
                       Plugin };

struct UnitEntry {
  UnitKind kind;
  std::string_view name;
  int number;
  UnitScope scope;
};

#define TESTBED_UNIT(kind, name, number, scope) inline constexpr int name = number;
#include "testbed/glsl/units.glsl"
#undef TESTBED_UNIT

#define TESTBED_UNIT(kind, name, number, scope) UnitEntry{UnitKind::kind, #name, number, UnitScope::scope},
inline constexpr UnitEntry kUnits[] = {
#include "testbed/glsl/units.glsl"
};
#undef TESTBED_UNIT

}  // namespace testbed
