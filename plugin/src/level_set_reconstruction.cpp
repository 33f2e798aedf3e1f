// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.cpp
/// @brief Explicit instantiations of pcl::LevelSetReconstruction for the common point types,
/// the PCL way (PCL_INSTANTIATE); other types: define PCL_NO_PRECOMPILE before including the
/// header.
#include "lsrecon/pcl/impl/level_set_reconstruction.hpp"

#include <pcl/impl/instantiate.hpp>
#include <pcl/point_types.h>

PCL_INSTANTIATE(LevelSetReconstruction, (pcl::PointXYZ)(pcl::PointXYZI)(pcl::PointXYZRGB)(pcl::PointXYZRGBA)
                                            (pcl::PointNormal)(pcl::PointXYZRGBNormal)(pcl::PointXYZINormal))
