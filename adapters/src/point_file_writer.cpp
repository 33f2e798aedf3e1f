// SPDX-License-Identifier: BSD-3-Clause
/// @file point_file_writer.cpp
#include "binary_scalars.h"
#include "lsrecon/adapters/atomic_file.h"
#include "lsrecon/adapters/point_files.h"
#include "lsrecon/core/errors.h"

#include <fstream>
#include <iomanip>

namespace lsr::adapters {

void write_points(const std::string& path, const Points<3>& points) {
  const bool ply = path.size() >= 4 && path.compare(path.size() - 4, 4, ".ply") == 0;
  write_file_atomically(path, [&](const std::string& file) {
    std::ofstream out(file, std::ios::binary);
    if (!out) throw Error("cannot write " + path, "check that the folder exists and is writable");
    if (ply) {
      out << "ply\nformat binary_" << (detail::host_is_little_endian() ? "little" : "big") << "_endian 1.0\nelement vertex "
          << points.size() << "\nproperty double x\nproperty double y\nproperty double z\nend_header\n";
      // Vec<3> is three packed doubles (no padding), in the host's byte order as declared.
      static_assert(sizeof(Vec<3>) == 3 * sizeof(double));
      out.write(reinterpret_cast<const char*>(points.data()), std::streamsize(points.size() * sizeof(Vec<3>)));
    } else {
      out << std::setprecision(17);
      for (const auto& p : points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    }
    if (!out.flush()) throw Error("writing " + path + " failed", "check free disk space");
  });
}

}  // namespace lsr::adapters
