#include "testbed/gl/pass_timer.h"

#include "testbed/core/error.h"

namespace testbed {

PassTimer::~PassTimer() {
  if (!pool_.empty()) glDeleteQueries(static_cast<GLsizei>(pool_.size()), pool_.data());
}

GLuint PassTimer::takeQuery() {
  if (used_ == pool_.size()) {
    GLuint query = 0;
    glGenQueries(1, &query);
    pool_.push_back(query);
  }
  return pool_[used_++];
}

PassTimer::Scope::Scope(PassTimer& timer, std::string name) : timer_(timer) {
  if (timer.open_) throw GlError("PassTimer: scope '" + name + "' opened inside another scope");
  timer.open_ = true;
  Entry entry{std::move(name), timer.takeQuery()};
  glFinish();
  start_ = std::chrono::steady_clock::now();
  glBeginQuery(GL_TIME_ELAPSED, entry.query);
  timer.entries_.push_back(std::move(entry));
}

PassTimer::Scope::~Scope() {
  glEndQuery(GL_TIME_ELAPSED);
  glFinish();
  timer_.entries_.back().wallMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  timer_.open_ = false;
}

PassTimes PassTimer::resolve() {
  PassTimes times;
  for (const Entry& entry : entries_) {
    GLuint64 nanoseconds = 0;
    glGetQueryObjectui64v(entry.query, GL_QUERY_RESULT, &nanoseconds);
    const double ms = double(nanoseconds) * 1e-6;
    if (!times.passMs.count(entry.name)) times.order.push_back(entry.name);
    times.passMs[entry.name] += ms;
    times.totalMs += ms;
    times.wallPassMs[entry.name] += entry.wallMs;
    times.wallTotalMs += entry.wallMs;
  }
  entries_.clear();
  used_ = 0;
  return times;
}

}  // namespace testbed
