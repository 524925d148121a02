#pragma once
// The GPU memory ledger: the bytes of the GL objects a technique creates, booked by the
// objects themselves (gl/objects.h), so a technique's memory footprint is measured from
// what it really allocates, never typed in.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace testbed {

// Whether a technique's paper has a resource (its shadow map, its own maps) or it is a
// device of the fast path (docs/paths.md).
enum class ResourceRole { Paper, Device };
std::string_view roleName(ResourceRole role);  // "paper" or "device"

// Sums the bytes of the GL objects created while it is the current ledger (see Scope);
// each object returns its bytes to the ledger it was booked in when it is destroyed. The
// sum is split by resource: the name and role of the Label current at the allocation, and
// the object's format.
class GpuMemoryLedger {
 public:
  GpuMemoryLedger() = default;
  GpuMemoryLedger(const GpuMemoryLedger&) = delete;
  GpuMemoryLedger& operator=(const GpuMemoryLedger&) = delete;

  struct Resource {
    std::string name, format;  // format: "R32F", "DEPTH_COMPONENT16", "buffer"
    ResourceRole role = ResourceRole::Paper;
    std::uint64_t bytes = 0;
    auto operator<=>(const Resource&) const = default;
  };
  std::uint64_t bytes() const { return bytes_; }
  // The live resources, those of one name, format and role summed, sorted by name.
  std::vector<Resource> resources() const;
  // `delta` bytes of `resource` (its bytes ignored).
  void add(const Resource& resource, std::int64_t delta);

  // Makes `ledger` current on this thread for the scope's lifetime (nests).
  class Scope {
   public:
    explicit Scope(GpuMemoryLedger& ledger);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    GpuMemoryLedger* previous_;
  };
  // Names what the GL objects created on this thread during its lifetime are (nests);
  // outside any, they are booked as "unnamed", paper.
  class Label {
   public:
    Label(std::string name, ResourceRole role);
    ~Label();
    Label(const Label&) = delete;
    Label& operator=(const Label&) = delete;

   private:
    std::string name_;
    ResourceRole role_;
    const Label* previous_;
    friend class GpuMemoryLedger;
  };
  static GpuMemoryLedger* current();
  // Every live object of the process, whatever ledger booked it.
  static std::uint64_t processBytes();

  // For the GL objects (gl/objects.h) that book themselves: the resource an allocation of
  // `format` made now is booked as (the current Label's name and role), and the count of
  // every live object's bytes that processBytes() reads.
  static Resource labelled(std::string_view format);
  static void addProcessBytes(std::int64_t delta);

 private:
  std::uint64_t bytes_ = 0;
  std::map<std::tuple<std::string, std::string, ResourceRole>, std::uint64_t> resources_;
};

}  // namespace testbed
