// SPDX-License-Identifier: BSD-3-Clause
/// @file pcl_mesh.cpp
#include "lsrecon/adapters/pcl_mesh.h"

#include "lsrecon/core/errors.h"

#include <pcl/common/io.h>

#include <algorithm>
#include <cstring>

namespace lsr::adapters {

pcl::PCLPointCloud2 scalar_field(const std::string& name, const std::vector<float>& values) {
  pcl::PCLPointCloud2 cloud;
  pcl::PCLPointField field;
  field.name = name;
  field.offset = 0;
  field.datatype = pcl::PCLPointField::FLOAT32;
  field.count = 1;
  cloud.fields = {field};
  cloud.width = std::uint32_t(values.size());
  cloud.height = 1;
  cloud.point_step = sizeof(float);
  cloud.row_step = cloud.point_step * cloud.width;
  cloud.is_dense = true;
  cloud.data.resize(values.size() * sizeof(float));
  if (!values.empty()) std::memcpy(cloud.data.data(), values.data(), cloud.data.size());
  return cloud;
}

void append_fields(const pcl::PCLPointCloud2& from, pcl::PCLPointCloud2& to) {
  const std::size_t n = std::size_t(to.width) * to.height;
  if (std::size_t(from.width) * from.height != n) {
    throw Error("cannot append the fields of " + std::to_string(std::size_t(from.width) * from.height) + " points to " +
                    std::to_string(n),
                "pass one value per vertex");
  }
  std::vector<pcl::PCLPointField> fields = to.fields, added;
  std::uint32_t step = to.point_step;
  for (const pcl::PCLPointField& f : from.fields) {
    const bool present = std::any_of(to.fields.begin(), to.fields.end(), [&](const auto& g) { return g.name == f.name; });
    if (present || f.name == "_") continue;  // "_": PCL's padding
    added.push_back(f);
    fields.push_back(f);
    fields.back().offset = step;
    step += std::uint32_t(pcl::getFieldSize(f.datatype)) * std::max<std::uint32_t>(f.count, 1);
  }
  if (added.empty()) return;
  std::vector<std::uint8_t> data(n * step);
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(&data[i * step], &to.data[i * to.point_step], to.point_step);
    for (std::size_t k = 0; k < added.size(); ++k) {
      const pcl::PCLPointField& f = added[k];
      const std::size_t size = std::size_t(pcl::getFieldSize(f.datatype)) * std::max<std::uint32_t>(f.count, 1);
      std::memcpy(&data[i * step + fields[to.fields.size() + k].offset], &from.data[i * from.point_step + f.offset], size);
    }
  }
  to.fields = std::move(fields);
  to.point_step = step;
  to.row_step = step * to.width;
  to.data = std::move(data);
}

}  // namespace lsr::adapters
