#pragma once
// Reading a file the user named: it must be a regular file (or a link to one) no larger
// than a cap. A device (/dev/zero), a FIFO or a socket is refused without reading from
// it or blocking on it, so a typo can neither hang a run nor exhaust its memory.
#include <cstdint>
#include <filesystem>
#include <string>

namespace testbed {

// Caps by kind of input: scene files and metrics.json are hand- or machine-written text
// of kilobytes; meshes are bounded by the scene's triangle limit (20 M triangles is 1 GB
// as binary STL).
inline constexpr std::uint64_t kMaxJsonInputBytes = 64ull << 20;
inline constexpr std::uint64_t kMaxMeshFileBytes = 4ull << 30;

// The whole file. Throws InputError "<file>: <problem>" (missing, not a regular file,
// larger than `maxBytes`, unreadable).
std::string readInputFile(const std::filesystem::path& file, std::uint64_t maxBytes);

// The same checks for readers that open the file by name themselves (OpenMesh); returns
// the file's size.
std::uint64_t checkInputFile(const std::filesystem::path& file, std::uint64_t maxBytes);

// "a folder", "a FIFO", "a device", ... for a stat mode, in messages.
std::string describeFileMode(unsigned mode);

}  // namespace testbed
