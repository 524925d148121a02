#include "testbed/gl/pass_timer.h"

#include <algorithm>

#include "testbed/core/error.h"

namespace testbed {

WorkCounts& operator+=(WorkCounts& sum, const WorkCounts& counts) {
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += counts[i];
  return sum;
}

bool workCountersAvailable() { return GLAD_GL_ARB_pipeline_statistics_query != 0; }

PassTimer::PassTimer(bool countWork) : countWork_(countWork && workCountersAvailable()) {}

PassTimer::~PassTimer() {
  for (const Slot& slot : pool_) glDeleteQueries(GLsizei(slot.size()), slot.data());
}

const PassTimer::Slot& PassTimer::takeSlot() {
  if (used_ == pool_.size()) {
    Slot slot{};
    glGenQueries(GLsizei(slot.size()), slot.data());
    pool_.push_back(slot);
  }
  return pool_[used_++];
}

PassTimer::Scope::Scope(PassTimer& timer, std::string name) : timer_(timer) {
  if (timer.declared_ && std::find(timer.declared_->begin(), timer.declared_->end(), name) == timer.declared_->end()) {
    std::string declared;
    for (const auto& d : *timer.declared_) declared += (declared.empty() ? "" : ", ") + d;
    throw UndeclaredPassError("pass '" + name + "' is not one the technique declares for this path (" + declared +
                              "): declare it in its TechniqueInfo::passes");
  }
  if (timer.open_) throw GlError("PassTimer: scope '" + name + "' opened inside another scope");
  timer.open_ = true;
  Entry entry{std::move(name), timer.takeSlot()};
  glFinish();
  start_ = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, entry.queries[0]);
  if (timer.countWork_)
    for (std::size_t i = 0; i < kWorkCounters.size(); ++i) glBeginQuery(kWorkCounters[i].target, entry.queries[1 + i]);
  timer.entries_.push_back(std::move(entry));
}

PassTimer::Scope::~Scope() {
  glEndQuery(GL_TIME_ELAPSED);
  if (timer_.countWork_)
    for (const WorkCounter& counter : kWorkCounters) glEndQuery(counter.target);
  glFinish();
  timer_.entries_.back().wallMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  timer_.open_ = false;
}

PassTimes PassTimer::resolve() {
  PassTimes times;
  if (countWork_) times.work.emplace();
  for (const Entry& entry : entries_) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(entry.queries[0], GL_QUERY_RESULT, &nanoseconds);
    const double ms = double(nanoseconds) * 1e-6;
    if (!times.passMs.count(entry.name)) times.order.push_back(entry.name);
    times.passMs[entry.name] += ms;
    times.totalMs += ms;
    times.wallPassMs[entry.name] += entry.wallMs;
    times.wallTotalMs += entry.wallMs;
    if (!times.work) continue;
    WorkCounts counts{};
    for (std::size_t i = 0; i < counts.size(); ++i) {
      GLuint64 count = 0;
      glGetQueryObjectui64v(entry.queries[1 + i], GL_QUERY_RESULT, &count);
      counts[i] = count;
    }
    times.work->passes[entry.name] += counts;  // a repeated name adds up, as its times do
    times.work->total += counts;
  }
  entries_.clear();
  used_ = 0;
  return times;
}

}  // namespace testbed
