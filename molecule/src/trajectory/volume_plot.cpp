// SPDX-License-Identifier: Apache-2.0
#include "trajectory/volume_plot.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "outputs/pocket_colors.hpp"

namespace molecule {
namespace {

// About five round steps (1, 2 or 5 times a power of ten) covering [0, hi].
double tick_step(double hi) {
  const double raw = std::max(hi, 1e-9) / 5, p = std::pow(10.0, std::floor(std::log10(raw)));
  return raw <= p ? p : raw <= 2 * p ? 2 * p : raw <= 5 * p ? 5 * p : 10 * p;
}

}  // namespace

std::string volume_plot_svg(const TrackResult& r, const std::vector<std::size_t>& tracks) {
  constexpr double W = 800, H = 450, left = 70, right = 170, top = 30, bottom = 60;
  // At least one frame's and one A^3's span: one frame, or no pocket, keeps round ticks.
  const double t0 = r.frames.front().time, t1 = std::max(r.frames.back().time, t0 + (r.time_in_ps ? 1e-3 : 1));
  double vmax = 1;
  for (std::size_t t : tracks)
    for (std::size_t o : r.tracks[t].observations) vmax = std::max(vmax, r.observations[o].sa_volume);
  const double vstep = tick_step(vmax), vtop = std::max(vstep, std::ceil(vmax / vstep) * vstep);
  const auto x = [&](double time) { return left + (W - left - right) * (time - t0) / (t1 - t0); };
  const auto y = [&](double v) { return H - bottom - (H - top - bottom) * v / vtop; };
  std::string s = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
      "font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{}\" y=\"18\" font-size=\"15\">Solvent-accessible volume of the top pockets</text>\n",
      W, H, left);
  for (double v = 0; v <= vtop + vstep / 2; v += vstep)
    s += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2:.1f}\" y2=\"{2:.1f}\" stroke=\"#ddd\"/>"
                     "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:g}</text>\n",
                     left, W - right, y(v), left - 6, y(v) + 4, v);
  const double tstep = tick_step(t1 - t0);
  for (double t = std::ceil(t0 / tstep) * tstep; t <= t1 + tstep * 1e-6; t += tstep)
    s += fmt::format("<line x1=\"{0:.1f}\" x2=\"{0:.1f}\" y1=\"{1}\" y2=\"{2}\" stroke=\"#000\"/>"
                     "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4:g}</text>\n",
                     x(t), H - bottom, H - bottom + 5, H - bottom + 20, t);
  s += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#000\"/>\n", left, top,
                   W - left - right, H - top - bottom);
  s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", (left + W - right) / 2, H - 15,
                   r.time_in_ps ? "time (ps)" : "frame");
  s += fmt::format("<text transform=\"translate(18 {}) rotate(-90)\" text-anchor=\"middle\">SA volume (\u00c5\u00b3)</text>\n",
                   (top + H - bottom) / 2);
  if (tracks.empty())
    s += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">no pocket in any frame</text>\n",
                     (left + W - right) / 2, (top + H - bottom) / 2);
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const Track& track = r.tracks[tracks[k]];
    const Rgb c = rank_color(k + 1);
    const std::string colour = fmt::format("rgb({},{},{})", c.r, c.g, c.b);
    // Runs of consecutive frames as polylines; a lone frame as a dot.
    std::vector<std::pair<double, double>> run;
    const auto flush = [&] {
      if (run.size() == 1)
        s += fmt::format("<circle r=\"2.5\" fill=\"{}\" cx=\"{:.1f}\" cy=\"{:.1f}\"/>\n", colour, run[0].first, run[0].second);
      if (run.size() > 1) {
        s += "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" + colour + "\" points=\"";
        for (const auto& [px, py] : run) s += fmt::format("{:.1f},{:.1f} ", px, py);
        s += "\"/>\n";
      }
      run.clear();
    };
    std::size_t last = 0;
    for (std::size_t o : track.observations) {
      const Observation& ob = r.observations[o];
      if (!run.empty() && ob.frame != last + 1) flush();
      run.emplace_back(x(r.frames[ob.frame].time), y(ob.sa_volume));
      last = ob.frame;
    }
    flush();
    const double ly = top + 20 + 22 * double(k);
    s += fmt::format("<line x1=\"{0}\" x2=\"{1}\" y1=\"{2}\" y2=\"{2}\" stroke=\"{3}\" stroke-width=\"3\"/>"
                     "<text x=\"{4}\" y=\"{5}\">pocket {6} ({7:.0f}%)</text>\n",
                     W - right + 12, W - right + 36, ly, colour, W - right + 42, ly + 4, track.id,
                     100 * r.frequency_of(track));
  }
  return s + "</svg>\n";
}

}  // namespace molecule
