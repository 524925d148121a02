#pragma once
// The shaded image for people (T.png): Lambert × visibility plus ambient, on the CPU from
// the G-buffer readback. Untimed, and no part of any metric.
#include "testbed/io/image_io.h"
#include "testbed/scene/view.h"

namespace testbed {

// `positions` (xyz world position, w coverage) and `normals` (xyz) are the G-buffer
// readback, top-down; `visibility` one channel of the same size. Returns RGB, the
// background where no receiver covers the pixel.
ImageF shadeVisibility(const ImageF& positions, const ImageF& normals, const LightTransforms& light,
                       const ImageF& visibility);

}  // namespace testbed
