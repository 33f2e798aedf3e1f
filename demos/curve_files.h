// SPDX-License-Identifier: BSD-3-Clause
/// @file curve_files.h
/// @brief Writing 2D results: SVG (closed paths, y up) and a plain polyline text format
/// ("# loop k" then "x y" per vertex), both atomically.
#pragma once

#include "lsrecon/core/atomic_file.h"
#include "lsrecon/core/errors.h"
#include "lsrecon/core/types.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <string>
#include <vector>

namespace lsr::demos {

inline void write_polylines(const std::string& path, const Points<2>& vertices,
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

/// @brief Points as text, "x y z" per line (2D input: z = 0), as lsrecon reads them back.
inline void write_points(const std::string& path, const Points<3>& points) {
  write_file_atomically(path, [&](const std::string& file) {
    std::ofstream out(file);
    if (!out) throw Error("cannot write " + path, "check that the folder exists and is writable");
    out << std::setprecision(17);
    for (const auto& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    if (!out.flush()) throw Error("writing " + path + " failed", "check free disk space");
  });
}

inline void write_svg(const std::string& path, const Points<2>& vertices,
                      const std::vector<std::vector<Index>>& loops, const Points<2>& data) {
  Vec<2> lo = Vec<2>::Constant(1e300), hi = Vec<2>::Constant(-1e300);
  for (const auto& p : data) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  for (const auto& p : vertices) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
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
    for (const auto& loop : loops) {
      out << "<path fill=\"none\" stroke=\"#1f3a93\" stroke-width=\"2\" d=\"";
      for (std::size_t i = 0; i < loop.size(); ++i) out << (i ? " L" : "M") << X(vertices[loop[i]]) << ',' << Y(vertices[loop[i]]);
      out << " Z\"/>\n";
    }
    out << "</svg>\n";
    if (!out.flush()) throw Error("writing " + path + " failed", "check free disk space");
  });
}

}  // namespace lsr::demos
