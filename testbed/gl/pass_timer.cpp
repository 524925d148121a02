#include "testbed/gl/pass_timer.h"

#include <algorithm>

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
  Entry entry{std::move(name), timer.takeQuery(), timer.takeQuery()};
  glQueryCounter(entry.begin, GL_TIMESTAMP);
  timer.entries_.push_back(std::move(entry));
}

PassTimer::Scope::~Scope() {
  glQueryCounter(timer_.entries_.back().end, GL_TIMESTAMP);
  timer_.open_ = false;
}

PassTimes PassTimer::resolve() {
  PassTimes times;
  GLuint64 first = ~GLuint64(0), last = 0;
  for (const Entry& entry : entries_) {
    GLuint64 begin = 0, end = 0;
    glGetQueryObjectui64v(entry.begin, GL_QUERY_RESULT, &begin);
    glGetQueryObjectui64v(entry.end, GL_QUERY_RESULT, &end);
    const double ms = end > begin ? double(end - begin) * 1e-6 : 0.0;
    if (!times.passMs.count(entry.name)) times.order.push_back(entry.name);
    times.passMs[entry.name] += ms;
    first = std::min(first, begin);
    last = std::max(last, end);
  }
  times.totalMs = last > first ? double(last - first) * 1e-6 : 0.0;
  entries_.clear();
  used_ = 0;
  return times;
}

}  // namespace testbed
