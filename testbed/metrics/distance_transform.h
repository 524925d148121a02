#pragma once
// Exact Euclidean distance transform on a pixel grid, used by the error metrics to measure
// how far pixels lie from a shadow boundary. Separable and linear in the pixel count
// (Felzenszwalb & Huttenlocher 2012: a 1D pass down each column, then the lower envelope
// of parabolas along each row), so full-resolution frames cost a few milliseconds.
#include <cstdint>
#include <span>
#include <vector>

namespace testbed {

// seeds: width*height values, row-major (index y*width + x), nonzero = seed pixel.
// Returns, per pixel in the same layout, the squared Euclidean distance in pixel units to
// the nearest seed. Squared distances are integers and are returned exactly (doubles hold
// them exactly); a seed's own value is 0. With no seed at all every value is +infinity.
// Throws std::invalid_argument when the sizes are negative or do not match seeds.size().
std::vector<double> squaredDistanceTransform(int width, int height, std::span<const std::uint8_t> seeds);

}  // namespace testbed
