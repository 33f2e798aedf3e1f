// SPDX-License-Identifier: BSD-3-Clause
/// @file registered_scans.cpp
/// @brief Range scans registered by a Stanford .conf file, as the Stanford 3D Scanning
/// Repository ships them (the bunny, the dragon, the Buddha): one line
/// `bmesh FILE tx ty tz qx qy qz qw` per scan, mapping a point p of FILE (a path relative to the
/// .conf) to R(q)^T p + t, R(q) the rotation of the unit quaternion (qx, qy, qz, qw). Read that
/// way the bunny's 10 overlapping scans agree to about the scanner's spacing (3e-4 m); with R(q)
/// instead of its transpose they lie 2e-3 to 7e-2 m apart. Other lines (`camera ...`) are
/// skipped.
#include "point_file_readers.h"

#include "lsrecon/adapters/file_formats.h"
#include "lsrecon/core/errors.h"

#include <Eigen/Geometry>

#include <fstream>
#include <sstream>

namespace lsr::adapters::detail {

PointFile read_registered_scans(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot open " + path, "check the path and the file's permissions");
  const char* const format = "a .conf file has a line 'bmesh FILE tx ty tz qx qy qz qw' per scan (Stanford's registration)";
  const std::size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  PointFile out;
  std::string line;
  for (long number = 1; std::getline(in, line); ++number) {
    std::istringstream s(line);
    std::string keyword, file;
    if (!(s >> keyword) || keyword != "bmesh") continue;
    double v[7];
    int n = 0;
    s >> file;
    while (n < 7 && s >> v[n]) ++n;
    const std::string where = path + ":" + std::to_string(number) + ": ";
    if (file.empty() || n != 7) throw Error(where + "expected a file name and 7 numbers after 'bmesh'", format);
    const Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);  // Eigen's order: w, x, y, z
    if (!(q.norm() > 0.0) || !q.coeffs().allFinite() || !Eigen::Vector3d(v[0], v[1], v[2]).allFinite()) {
      throw Error(where + "the translation must be finite and the quaternion finite and non-zero", format);
    }
    if (file_extension(file) == "conf") throw Error(where + "a .conf file lists scans, not other .conf files", format);
    const std::string scan = file.front() == '/' ? file : folder + file;
    const Eigen::Matrix3d rotation_transposed = q.normalized().toRotationMatrix().transpose();
    PointFile part = read_point_file(scan);
    for (const Vec<3>& p : part.points) out.points.push_back(rotation_transposed * p + Eigen::Vector3d(v[0], v[1], v[2]));
    out.skipped += part.skipped;
  }
  if (out.points.empty() && out.skipped == 0) throw Error(path + " lists no scan", format);
  return out;
}

}  // namespace lsr::adapters::detail
