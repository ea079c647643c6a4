#include "io/history.h"

#include "core/errors.h"
#include "io/text_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace froth {
namespace {

void require_rows(const std::vector<HistoryRow>& rows, const char* op) {
    if (rows.empty()) throw InvalidInput(std::string(op) + ": the history has no rows");
}

/// About five "nice" tick values (1, 2 or 5 times a power of ten) covering [lo, hi].
std::vector<double> ticks(double lo, double hi) {
    const double span = hi - lo, raw = span / 5;
    const double power = std::pow(10.0, std::floor(std::log10(raw)));
    const double step = raw / power < 2 ? 2 * power : raw / power < 5 ? 5 * power : 10 * power;
    std::vector<double> t;
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step)
        t.push_back(std::abs(v) < 1e-12 * span ? 0.0 : v);
    return t;
}

std::string label(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

} // namespace

void write_history_csv(const std::string& path, const std::vector<HistoryRow>& rows) {
    require_rows(rows, "history");
    io::TextBuffer b;
    b << "t,tau,energy,volume_loss";
    for (std::size_t k = 0; k < rows.front().volumes.size(); ++k)
        b << ",V" << static_cast<int>(k + 1);
    b << '\n';
    for (const HistoryRow& r : rows) {
        b << r.t << ',' << r.tau << ',' << r.energy << ',' << r.volume_loss;
        for (double v : r.volumes) b << ',' << v;
        b << '\n';
    }
    io::write_text_file(path, b.str(), "history");
}

void write_history_svg(const std::string& path, const std::vector<HistoryRow>& rows,
                       const std::string& title) {
    require_rows(rows, "history");
    const double W = 720, H = 440, left = 90, right = 20, top = 40, bottom = 60;
    double t0 = rows.front().t, t1 = rows.back().t;
    auto [lo_it, hi_it] = std::minmax_element(rows.begin(), rows.end(),
        [](const HistoryRow& a, const HistoryRow& b) { return a.energy < b.energy; });
    double e0 = lo_it->energy, e1 = hi_it->energy;
    if (t1 <= t0) t1 = t0 + 1;
    if (e1 - e0 <= 1e-12 * std::max(1.0, std::abs(e1))) { // a flat line: give it some room
        const double half = std::max(1e-9, 1e-6 * std::abs(e1));
        e0 -= half, e1 += half;
    }
    const double pad = 0.05 * (e1 - e0);
    e0 -= pad, e1 += pad;
    auto x = [&](double t) { return left + (t - t0) / (t1 - t0) * (W - left - right); };
    auto y = [&](double e) { return H - bottom - (e - e0) / (e1 - e0) * (H - top - bottom); };

    io::TextBuffer b;
    b << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << W / 2
      << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">";
    b.xml_escaped(title) << "</text>\n";
    b << "<g stroke=\"#999\" stroke-width=\"1\">\n";
    for (double t : ticks(t0, t1))
        b << "<line x1=\"" << x(t) << "\" y1=\"" << top << "\" x2=\"" << x(t) << "\" y2=\""
          << H - bottom << "\" stroke-dasharray=\"2,4\"/>\n";
    for (double e : ticks(e0, e1))
        b << "<line x1=\"" << left << "\" y1=\"" << y(e) << "\" x2=\"" << W - right << "\" y2=\""
          << y(e) << "\" stroke-dasharray=\"2,4\"/>\n";
    b << "</g>\n<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << W - left - right
      << "\" height=\"" << H - top - bottom << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (double t : ticks(t0, t1))
        b << "<text x=\"" << x(t) << "\" y=\"" << H - bottom + 18
          << "\" text-anchor=\"middle\">" << label(t) << "</text>\n";
    for (double e : ticks(e0, e1))
        b << "<text x=\"" << left - 6 << "\" y=\"" << y(e) + 4 << "\" text-anchor=\"end\">"
          << label(e) << "</text>\n";
    b << "<text x=\"" << (left + W - right) / 2 << "\" y=\"" << H - 15
      << "\" text-anchor=\"middle\">t</text>\n<text x=\"20\" y=\"" << (top + H - bottom) / 2
      << "\" text-anchor=\"middle\" transform=\"rotate(-90 20 " << (top + H - bottom) / 2
      << ")\">energy</text>\n<polyline fill=\"none\" stroke=\"#1f5fbf\" stroke-width=\"1.5\" "
         "points=\"";
    for (const HistoryRow& r : rows) b << x(r.t) << ',' << y(r.energy) << ' ';
    b << "\"/>\n</svg>\n";
    io::write_text_file(path, b.str(), "history");
}

} // namespace froth
