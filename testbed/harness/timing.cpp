#include "testbed/harness/timing.h"

#include <algorithm>

namespace testbed {

bool isSoftwareRasterizer(std::string_view renderer) {
  for (const char* software : {"llvmpipe", "softpipe", "swrast"})
    if (renderer.find(software) != std::string_view::npos) return true;
  return false;
}

TimingSource timingSourceFor(std::string_view backend) {
  return isSoftwareRasterizer(backend) ? TimingSource::Wall : TimingSource::Gpu;
}

std::string_view timingName(TimingSource source) { return source == TimingSource::Wall ? "wall" : "gpu"; }

double frameTimeMs(const PassTimes& times, TimingSource source) {
  return source == TimingSource::Wall ? times.wallTotalMs : times.totalMs;
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

PassTimes medianPassTimes(const std::vector<PassTimes>& frames) {
  PassTimes result;
  if (frames.empty()) return result;
  result.order = frames.front().order;
  for (const auto& name : result.order) {
    std::vector<double> gpu, wall;
    for (const auto& f : frames) {
      gpu.push_back(f.passMs.at(name));
      wall.push_back(f.wallPassMs.at(name));
    }
    result.passMs[name] = median(gpu);
    result.wallPassMs[name] = median(wall);
    result.totalMs += result.passMs[name];
    result.wallTotalMs += result.wallPassMs[name];
  }
  return result;
}

}  // namespace testbed
