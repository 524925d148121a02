#include "testbed/gl/memory_ledger.h"

#include <atomic>

namespace testbed {
namespace {

thread_local GpuMemoryLedger* t_currentLedger = nullptr;
thread_local const GpuMemoryLedger::Label* t_currentLabel = nullptr;
std::atomic<std::uint64_t> g_processBytes{0};

}  // namespace

GpuMemoryLedger::Scope::Scope(GpuMemoryLedger& ledger) : previous_(t_currentLedger) {
  t_currentLedger = &ledger;
}
GpuMemoryLedger::Scope::~Scope() { t_currentLedger = previous_; }
GpuMemoryLedger* GpuMemoryLedger::current() { return t_currentLedger; }
std::uint64_t GpuMemoryLedger::processBytes() { return g_processBytes.load(); }

std::vector<GpuMemoryLedger::Resource> GpuMemoryLedger::resources() const {
  std::vector<Resource> out;
  for (const auto& [key, bytes] : resources_)
    out.push_back({std::get<0>(key), std::get<1>(key), std::get<2>(key), bytes});
  return out;
}

void GpuMemoryLedger::add(const Resource& resource, std::int64_t delta) {
  bytes_ += static_cast<std::uint64_t>(delta);
  const auto key = std::make_tuple(resource.name, resource.format, resource.role);
  if ((resources_[key] += static_cast<std::uint64_t>(delta)) == 0) resources_.erase(key);
}

GpuMemoryLedger::Label::Label(std::string name, ResourceRole role)
    : name_(std::move(name)), role_(role), previous_(t_currentLabel) {
  t_currentLabel = this;
}
GpuMemoryLedger::Label::~Label() { t_currentLabel = previous_; }

GpuMemoryLedger::Resource GpuMemoryLedger::labelled(std::string_view format) {
  return {t_currentLabel ? t_currentLabel->name_ : "unnamed", std::string(format),
          t_currentLabel ? t_currentLabel->role_ : ResourceRole::Paper, 0};
}

void GpuMemoryLedger::addProcessBytes(std::int64_t delta) { g_processBytes += static_cast<std::uint64_t>(delta); }

}  // namespace testbed
