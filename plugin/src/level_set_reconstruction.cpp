// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction.cpp
/// @brief Explicit instantiations of pcl::LevelSetReconstruction for the common point types;
/// other types: define PCL_NO_PRECOMPILE before including the header.
#include "lsrecon/pcl/impl/level_set_reconstruction.hpp"

template class pcl::LevelSetReconstruction<pcl::PointXYZ>;
template class pcl::LevelSetReconstruction<pcl::PointXYZI>;
template class pcl::LevelSetReconstruction<pcl::PointXYZRGB>;
template class pcl::LevelSetReconstruction<pcl::PointXYZRGBA>;
template class pcl::LevelSetReconstruction<pcl::PointNormal>;
template class pcl::LevelSetReconstruction<pcl::PointXYZRGBNormal>;
template class pcl::LevelSetReconstruction<pcl::PointXYZINormal>;
