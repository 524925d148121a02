// speed_vs_error.svg: GPU time ratio to sm against boundary_px.mean. A plain SVG written
// by hand: a scatter plot of a handful of labelled points needs no plotting library.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "testbed/harness/metric_table.h"
#include "testbed/report/comparison.h"

namespace testbed {
namespace {

// A "nice" axis end and tick step covering [0, maximum].
std::pair<double, double> niceAxis(double maximum) {
  if (!(maximum > 0)) maximum = 1;
  const double raw = maximum / 5;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double factor : {1.0, 2.0, 5.0, 10.0})
    if (factor * magnitude >= raw) {
      step = factor * magnitude;
      break;
    }
  return {std::ceil(maximum / step) * step, step};
}

std::string escape(const std::string& text) {
  std::string out;
  for (char ch : text) {
    if (ch == '<') out += "&lt;";
    else if (ch == '>') out += "&gt;";
    else if (ch == '&') out += "&amp;";
    else out += ch;
  }
  return out;
}

}  // namespace

std::string speedVsErrorSvg(const Comparison& c) {
  constexpr double W = 640, H = 440, left = 70, right = 30, top = 40, bottom = 60;
  struct Point {
    std::string label;
    double x, y;
  };
  std::vector<Point> points;
  double maxX = 0, maxY = 0;
  const Metric &speed = metric("x_sm"), &error = metric("boundary_px.mean");
  for (const auto& entry : c.entries) {
    const double x = speed.value(entry.record, &baselineRecord(c)).value_or(NAN);
    const double y = error.value(entry.record, nullptr).value_or(NAN);
    points.push_back({entry.record.technique, x, y});
    if (std::isfinite(x)) maxX = std::max(maxX, x);
    if (std::isfinite(y)) maxY = std::max(maxY, y);
  }
  const auto [xEnd, xStep] = niceAxis(maxX * 1.1);
  const auto [yEnd, yStep] = niceAxis(maxY * 1.1);
  auto px = [&](double x) { return left + x / xEnd * (W - left - right); };
  auto py = [&](double y) { return H - bottom - y / yEnd * (H - top - bottom); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"DejaVu Sans, sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << W / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">" << escape(c.scene)
      << ": speed against error</text>\n";
  for (double x = 0; x <= xEnd + 1e-9; x += xStep)
    svg << "<line x1=\"" << px(x) << "\" y1=\"" << top << "\" x2=\"" << px(x) << "\" y2=\"" << H - bottom
        << "\" stroke=\"#ddd\"/><text x=\"" << px(x) << "\" y=\"" << H - bottom + 16
        << "\" text-anchor=\"middle\">" << x << "</text>\n";
  for (double y = 0; y <= yEnd + 1e-9; y += yStep)
    svg << "<line x1=\"" << left << "\" y1=\"" << py(y) << "\" x2=\"" << W - right << "\" y2=\"" << py(y)
        << "\" stroke=\"#ddd\"/><text x=\"" << left - 6 << "\" y=\"" << py(y) + 4 << "\" text-anchor=\"end\">" << y
        << "</text>\n";
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << W - left - right << "\" height=\""
      << H - top - bottom << "\" fill=\"none\" stroke=\"black\"/>\n"
      << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 18
      << "\" text-anchor=\"middle\">frame time / sm's (same run)</text>\n"
      << "<text transform=\"translate(18," << (top + H - bottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << error.name << " (pixels)</text>\n";
  for (const auto& p : points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    svg << "<circle cx=\"" << px(p.x) << "\" cy=\"" << py(p.y) << "\" r=\"4\" fill=\"#c03\"/>"
        << "<text x=\"" << px(p.x) + 7 << "\" y=\"" << py(p.y) - 6 << "\">" << escape(p.label) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace testbed
