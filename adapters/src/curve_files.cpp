// SPDX-License-Identifier: BSD-3-Clause
/// @file curve_files.cpp
#include "lsrecon/adapters/curve_files.h"

#include "lsrecon/adapters/atomic_file.h"
#include "lsrecon/core/errors.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace lsr::adapters {

Curves read_polylines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open " + path, "check the path");
  Curves c;
  int number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (line.rfind("# loop", 0) == 0) {
      c.loops.emplace_back();
      continue;
    }
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double x = 0, y = 0;
    if (!(fields >> x >> y) || !std::isfinite(x) || !std::isfinite(y)) {
      throw Error(path + ":" + std::to_string(number) + ": expected 'x y'", "write one vertex per line");
    }
    if (c.loops.empty()) c.loops.emplace_back();
    c.loops.back().push_back(Index(c.vertices.size()));
    c.vertices.emplace_back(x, y);
  }
  if (c.loops.empty()) throw Error(path + " holds no curve", "write '# loop 0' and then 'x y' per vertex");
  for (const auto& loop : c.loops) {
    if (loop.size() < 3) throw Error(path + " has a loop of fewer than 3 vertices", "close every curve with at least 3");
  }
  return c;
}

void write_polylines(const std::string& path, const Points<2>& vertices,
                            const std::vector<std::vector<Index>>& loops) {
  write_file_atomically(path, [&](const std::string& file) {
    std::ofstream out(file);
    if (!out) throw Error("cannot write " + path, "check that the folder exists and is writable");
    out << std::setprecision(10) << "# lsrecon closed curves: " << loops.size() << " loops, x y per line\n";
    for (std::size_t l = 0; l < loops.size(); ++l) {
      out << "# loop " << l << " (" << loops[l].size() << " vertices, closed)\n";
      for (Index v : loops[l]) out << vertices[v].x() << ' ' << vertices[v].y() << '\n';
    }
    if (!out.flush()) throw Error("writing " + path + " failed", "check free disk space");
  });
}

void write_svg(const std::string& path, const Points<2>& vertices,
                      const std::vector<std::vector<Index>>& loops, const Points<2>& data,
                      const Curves* start) {
  Vec<2> lo = Vec<2>::Constant(1e300), hi = Vec<2>::Constant(-1e300);
  for (const auto& p : data) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (const auto& p : vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (start) {
    for (const auto& p : start->vertices) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
  }
  const double size = std::max((hi - lo).maxCoeff(), 1e-300);
  const double scale = 1000.0 / size;
  auto X = [&](const Vec<2>& p) { return 20 + (p.x() - lo.x()) * scale; };
  auto Y = [&](const Vec<2>& p) { return 20 + (hi.y() - p.y()) * scale; };  // SVG y points down
  write_file_atomically(path, [&](const std::string& file) {
    std::ofstream out(file);
    if (!out) throw Error("cannot write " + path, "check that the folder exists and is writable");
    out << std::setprecision(7) << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << 40 + (hi.x() - lo.x()) * scale
        << "\" height=\"" << 40 + (hi.y() - lo.y()) * scale << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    for (const auto& p : data) out << "<circle cx=\"" << X(p) << "\" cy=\"" << Y(p) << "\" r=\"1.2\" fill=\"#999\"/>\n";
    auto path_of = [&](const Points<2>& x, const std::vector<Index>& loop, const char* style) {
      out << "<path fill=\"none\" " << style << " d=\"";
      for (std::size_t i = 0; i < loop.size(); ++i) out << (i ? " L" : "M") << X(x[loop[i]]) << ',' << Y(x[loop[i]]);
      out << " Z\"/>\n";
    };
    if (start) {
      for (const auto& loop : start->loops) path_of(start->vertices, loop, "stroke=\"#888\" stroke-width=\"2\" stroke-dasharray=\"8 6\"");
    }
    for (const auto& loop : loops) path_of(vertices, loop, "stroke=\"#1f3a93\" stroke-width=\"2\"");
    out << "</svg>\n";
    if (!out.flush()) throw Error("writing " + path + " failed", "check free disk space");
  });
}

}  // namespace lsr::adapters
