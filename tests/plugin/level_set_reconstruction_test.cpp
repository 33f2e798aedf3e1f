// SPDX-License-Identifier: BSD-3-Clause
/// @file level_set_reconstruction_test.cpp
/// @brief pcl::LevelSetReconstruction used exactly like pcl::Poisson.
#include "checks/exact_self_intersections.h"
#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/adapters/pcl_openmesh.h"
#include "lsrecon/pcl/level_set_reconstruction.h"
#include "lsrecon/testdata/analytic_shapes.h"
#include "lsrecon/testdata/shape_corpus.h"
#include "surface/surface_topology.h"

#include <pcl/common/io.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <thread>
#include <vector>

namespace {

template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr torus_cloud(int n) {
  typename pcl::PointCloud<PointT>::Ptr cloud(new pcl::PointCloud<PointT>);
  for (const auto& p : lsr::Torus{lsr::Vec<3>(0, 0, 0), 1.0, 0.4}.sample(n)) {
    PointT q;
    q.x = float(p.x());
    q.y = float(p.y());
    q.z = float(p.z());
    cloud->push_back(q);
  }
  PointT bad;
  bad.x = bad.y = bad.z = std::numeric_limits<float>::quiet_NaN();
  cloud->push_back(bad);  // PCL clouds carry NaNs: skipped
  return cloud;
}

template <typename PointT>
void check_torus() {
  pcl::LevelSetReconstruction<PointT> ls;
  ls.setInputCloud(torus_cloud<PointT>(8000));
  ls.setResolution(0.07);  // cloud units: the torus's tube has radius 0.4
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  ASSERT_TRUE(ls.getStatus().ok);
  EXPECT_TRUE(ls.getStatus().converged);
  EXPECT_EQ(ls.getStatus().skipped_points, 1u);
  EXPECT_EQ(ls.getStatus().dimension, 3);
  lsr::Points<3> vertices;
  std::vector<std::array<lsr::Index, 3>> triangles;
  lsr::adapters::triangles_from_polygon_mesh(mesh, vertices, triangles);
  ASSERT_EQ(triangles.size(), mesh.polygons.size());
  const lsr::SurfaceTopology t = lsr::analyze_surface(vertices, triangles);
  EXPECT_TRUE(t.watertight && t.oriented && t.edge_manifold && t.vertex_manifold);
  EXPECT_EQ(t.components, 1);
  EXPECT_EQ(t.genus, std::vector<int>{1});
  EXPECT_EQ(lsr::testing::cgal_self_intersections(vertices, triangles), 0u);  // embedded, in PCL's floats
  // Shared vertices with normals, not a triangle soup.
  EXPECT_LT(vertices.size(), 3 * triangles.size() / 2 + 1);
  pcl::PointCloud<pcl::PointNormal> normals;
  pcl::fromPCLPointCloud2(mesh.cloud, normals);
  for (const auto& p : normals) EXPECT_NEAR(std::hypot(p.normal_x, p.normal_y, p.normal_z), 1.0, 1e-5);
}

TEST(PclLevelSetReconstruction, TorusFromPointXYZIsWatertightGenusOneWithNormals) { check_torus<pcl::PointXYZ>(); }

TEST(PclLevelSetReconstruction, PointNormalWorksAndReceivesNormals) {
  check_torus<pcl::PointNormal>();
  pcl::LevelSetReconstruction<pcl::PointNormal> ls;
  ls.setInputCloud(torus_cloud<pcl::PointNormal>(4000));
  ls.setResolution(0.1);
  pcl::PointCloud<pcl::PointNormal> points;
  std::vector<pcl::Vertices> polygons;
  ls.reconstruct(points, polygons);
  ASSERT_FALSE(polygons.empty());
  // Normals point outwards: away from the torus's core circle.
  int outward = 0;
  for (const auto& p : points) {
    const lsr::Vec<3> x(p.x, p.y, p.z);
    const lsr::Vec<3> core = lsr::Vec<3>(x.x(), x.y(), 0).normalized();
    outward += (x - core).dot(lsr::Vec<3>(p.normal_x, p.normal_y, p.normal_z)) > 0 ? 1 : 0;
  }
  EXPECT_GE(outward, int(0.99 * points.size()));
}

TEST(PclLevelSetReconstruction, OpenMeshOutputIsAClosedMeshWithNormals) {
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(torus_cloud<pcl::PointXYZ>(4000));
  ls.setResolution(0.1);
  pcl::PolygonMesh polygons;
  ls.reconstruct(polygons);
  const lsr::adapters::TriMesh mesh = lsr::adapters::to_openmesh(polygons);
  const lsr::LevelSetMesh<3> back = lsr::adapters::from_openmesh(mesh);
  const lsr::SurfaceTopology t = lsr::analyze_surface(back.vertices, back.facets);
  EXPECT_TRUE(t.watertight && t.oriented);
  EXPECT_EQ(t.genus, std::vector<int>{1});
  EXPECT_TRUE(mesh.has_vertex_normals());
  EXPECT_TRUE(lsr::adapters::distance_to_data(mesh).has_value());
}

// Colours and intensities come from each vertex's nearest input point, and the distance to it
// is that point's: checked against a brute-force search over the cloud.
template <typename PointT>
void check_fields_of_nearest_points() {
  typename pcl::PointCloud<PointT>::Ptr cloud = torus_cloud<PointT>(3000);
  for (std::size_t i = 0; i < cloud->size(); ++i) {  // a field that differs from point to point
    if constexpr (pcl::traits::has_color_v<PointT>) (*cloud)[i].rgba = std::uint32_t(0xff000000u | (i * 2654435761u % 0xffffffu));
    if constexpr (pcl::traits::has_intensity_v<PointT>) (*cloud)[i].intensity = float(i);
  }
  pcl::LevelSetReconstruction<PointT> ls;
  ls.setInputCloud(cloud);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  ASSERT_TRUE(ls.getStatus().ok);
  pcl::PointCloud<PointT> vertices;
  pcl::fromPCLPointCloud2(mesh.cloud, vertices);
  const int distance_field = pcl::getFieldIndex(mesh.cloud, "distance");
  ASSERT_GE(distance_field, 0);
  ASSERT_FALSE(vertices.empty());
  std::size_t same = 0;
  for (std::size_t v = 0; v < vertices.size(); ++v) {
    std::vector<double> d(cloud->size());
    for (std::size_t i = 0; i < cloud->size(); ++i) {
      d[i] = ((*cloud)[i].getVector3fMap() - vertices[v].getVector3fMap()).template cast<double>().norm();
    }
    const double best = *std::min_element(d.begin(), d.end());
    float distance = 0.0f;
    std::memcpy(&distance, &mesh.cloud.data[v * mesh.cloud.point_step + mesh.cloud.fields[std::size_t(distance_field)].offset],
                sizeof distance);
    // float coordinates: the distances agree to a few float ulps of the coordinates (|x| < 2)
    EXPECT_NEAR(distance, best, 1e-5);
    // The fields of a nearest point (the sample has exact ties: it is symmetric).
    bool found = false;
    for (std::size_t i = 0; i < cloud->size() && !found; ++i) {
      if (d[i] > best + 1e-6) continue;
      bool equal = true;
      if constexpr (pcl::traits::has_color_v<PointT>) equal = equal && vertices[v].rgba == (*cloud)[i].rgba;
      if constexpr (pcl::traits::has_intensity_v<PointT>) equal = equal && vertices[v].intensity == (*cloud)[i].intensity;
      found = equal;
    }
    same += found;
  }
  EXPECT_EQ(same, vertices.size());
  // The same fields on the PointT output.
  pcl::PointCloud<PointT> points;
  std::vector<pcl::Vertices> polygons;
  ls.reconstruct(points, polygons);
  ASSERT_EQ(points.size(), vertices.size());
  for (std::size_t v = 0; v < points.size(); ++v) {
    if constexpr (pcl::traits::has_color_v<PointT>) {
      EXPECT_EQ(points[v].rgba, vertices[v].rgba);
    }
    if constexpr (pcl::traits::has_intensity_v<PointT>) {
      EXPECT_EQ(points[v].intensity, vertices[v].intensity);
    }
  }
}

TEST(PclLevelSetReconstruction, VerticesTakeTheColourOfTheNearestPoint) { check_fields_of_nearest_points<pcl::PointXYZRGB>(); }

TEST(PclLevelSetReconstruction, VerticesTakeTheIntensityOfTheNearestPoint) { check_fields_of_nearest_points<pcl::PointXYZI>(); }

TEST(PclLevelSetReconstruction, PlanarCloudGivesClosedLoopsInOrder) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& c : {lsr::Circle{lsr::Vec<2>(-1.2, 0), 0.5}, lsr::Circle{lsr::Vec<2>(1.2, 0), 0.5}}) {
    for (const auto& p : c.sample(800)) cloud->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), 2.5f));
  }
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(cloud);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  EXPECT_EQ(ls.getStatus().dimension, 2);
  ASSERT_EQ(mesh.polygons.size(), 2u);
  pcl::PointCloud<pcl::PointXYZ> vertices;
  pcl::fromPCLPointCloud2(mesh.cloud, vertices);
  for (const auto& loop : mesh.polygons) {
    // Consecutive vertices of a loop are neighbours on the curve.
    for (std::size_t i = 0; i < loop.vertices.size(); ++i) {
      const auto& a = vertices[loop.vertices[i]];
      const auto& b = vertices[loop.vertices[(i + 1) % loop.vertices.size()]];
      EXPECT_LT(std::hypot(a.x - b.x, a.y - b.y), 0.05);
      EXPECT_FLOAT_EQ(a.z, 2.5f);
    }
  }
}

TEST(PclLevelSetReconstruction, MissingOrBadInputLeavesTheOutputEmpty) {
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  pcl::PolygonMesh mesh;
  mesh.polygons.resize(3);
  ls.reconstruct(mesh);  // no input cloud: no crash
  EXPECT_TRUE(mesh.polygons.empty());
  EXPECT_FALSE(ls.getStatus().ok);

  pcl::PointCloud<pcl::PointXYZ>::Ptr line(new pcl::PointCloud<pcl::PointXYZ>);
  for (int i = 0; i < 50; ++i) line->push_back(pcl::PointXYZ(float(i), float(2 * i), float(3 * i)));
  ls.setInputCloud(line);
  ls.reconstruct(mesh);
  EXPECT_TRUE(mesh.polygons.empty());
  EXPECT_FALSE(ls.getStatus().ok);
  pcl::PointCloud<pcl::PointXYZ> points;
  std::vector<pcl::Vertices> polygons(2);
  ls.reconstruct(points, polygons);
  EXPECT_TRUE(polygons.empty());
  EXPECT_TRUE(points.empty());

  // Beyond the memory limit: refused, said in the status, then fine once the limit is lifted.
  pcl::PointCloud<pcl::PointXYZ>::Ptr sphere(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : lsr::Sphere{lsr::Vec<3>(0, 0, 0), 1.0}.sample(2000)) sphere->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  ls.setInputCloud(sphere);
  ls.setMaxMemory(1e6);  // 2,000 points at 1 KB and a 10,000-vertex mesh at 3 KB do not fit
  ls.reconstruct(mesh);
  EXPECT_TRUE(mesh.polygons.empty());
  EXPECT_FALSE(ls.getStatus().ok);
  EXPECT_NE(ls.getStatus().message.find("memory limit"), std::string::npos) << ls.getStatus().message;
  ls.setMaxMemory(0.0);
  ls.reconstruct(mesh);
  EXPECT_TRUE(ls.getStatus().ok) << ls.getStatus().message;
  EXPECT_FALSE(mesh.polygons.empty());
}

TEST(PclLevelSetReconstruction, HonoursIndicesAndSetters) {
  auto cloud = torus_cloud<pcl::PointXYZ>(4000);
  pcl::IndicesPtr half(new pcl::Indices);
  for (int i = 0; i < int(cloud->size()); i += 2) half->push_back(i);
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(cloud);
  ls.setIndices(half);
  ls.setResolution(0.1);
  ls.setMaxIterations(1);  // the front's distance to the data is first measured at step 2
  EXPECT_DOUBLE_EQ(ls.getResolution(), 0.1);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  EXPECT_TRUE(ls.getStatus().ok);
  EXPECT_EQ(ls.getStatus().iterations, 1);
  EXPECT_FALSE(ls.getStatus().converged);
}

}  // namespace

namespace {

TEST(PclLevelSetReconstruction, InputNormalsAreAlignedWithTheCloudAndOutward) {
  // A random torus with one NaN point: one normal per cloud point, NaN where skipped, outward
  // (the dot product with the true normal is positive) everywhere else.
  const lsr::TestShape shape = lsr::make_test_shape("torus");
  const lsr::SampledShape sample = lsr::sample_test_shape(shape, 3000);
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : sample.points) cloud->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  (*cloud)[10] = pcl::PointXYZ(nan, nan, nan);
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(cloud);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  ASSERT_TRUE(ls.getStatus().ok);
  const auto& normals = ls.getInputNormals();
  ASSERT_EQ(normals.size(), cloud->size());
  EXPECT_TRUE(std::isnan(normals[10].normal_x));
  for (std::size_t i = 0; i < cloud->size(); ++i) {
    if (i == 10) continue;
    const Eigen::Vector3d n(normals[i].normal_x, normals[i].normal_y, normals[i].normal_z);
    EXPECT_NEAR(n.norm(), 1.0, 1e-5);
    EXPECT_GT(n.dot(sample.normals[i]), 0.0) << "point " << i;
  }
}

// A cluster of outliers defeats the isolated-point rule (each has close neighbours) and becomes
// a component of its own; PCL's statistical filter, asked for, removes it first.
TEST(PclLevelSetReconstruction, StatisticalFilterRemovesAClusterOfOutliers) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : lsr::sample_test_shape(lsr::make_test_shape("sphere"), 3000).points) {
    cloud->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  }
  const std::size_t genuine = cloud->size();
  const Eigen::Vector3f far = (*cloud)[0].getVector3fMap() * 1.5f;
  for (int k = 0; k < 6; ++k) cloud->push_back(pcl::PointXYZ(far.x() + 0.01f * k, far.y(), far.z() - 0.01f * k));
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(cloud);
  ls.setStatisticalOutlierFilter(16, 3.0);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  ASSERT_TRUE(ls.getStatus().ok) << ls.getStatus().message;
  EXPECT_GE(ls.getStatus().statistical_outlier_points, 6u);
  EXPECT_LE(ls.getStatus().statistical_outlier_points, 6u + genuine / 100);  // see statistical_outliers_test
  for (std::size_t i = genuine; i < cloud->size(); ++i) EXPECT_TRUE(std::isnan(ls.getInputNormals()[i].normal_x));
  lsr::Points<3> vertices;
  std::vector<std::array<lsr::Index, 3>> triangles;
  lsr::adapters::triangles_from_polygon_mesh(mesh, vertices, triangles);
  const lsr::SurfaceTopology t = lsr::analyze_surface(vertices, triangles);
  EXPECT_EQ(t.components, 1);
  EXPECT_TRUE(t.watertight);
}

// The inside/outside meshes through the PCL class: their interface is the polygon mesh.
TEST(PclLevelSetReconstruction, VolumeMeshSharesTheSurface) {
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(torus_cloud<pcl::PointXYZ>(3000));
  ls.setVolumeMeshOutput(true);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  ASSERT_TRUE(ls.getStatus().ok);
  const lsr::VolumeMesh<3>& v = ls.getVolumeMesh3D();
  EXPECT_EQ(v.interface.size(), mesh.polygons.size());
  EXPECT_EQ(lsr::volume_mesh_quality(v).inverted, 0u);
  EXPECT_TRUE(ls.getVolumeMesh2D().simplices.empty());
  ls.setVolumeMeshOutput(false);
  ls.reconstruct(mesh);
  EXPECT_TRUE(ls.getVolumeMesh3D().simplices.empty());
}

// The library contract (run under the sanitizers too): NaN-only clouds and indices out of range
// are refused or skipped, an object reused on a second cloud forgets the first, and two objects
// on two threads at once give what each gives alone.
TEST(PclLevelSetReconstruction, NaNOnlyCloudsAndIndicesOutOfRangeAreReportedNotRead) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ>::Ptr nans(new pcl::PointCloud<pcl::PointXYZ>);
  for (int i = 0; i < 10; ++i) nans->push_back(pcl::PointXYZ(nan, nan, nan));
  pcl::LevelSetReconstruction<pcl::PointXYZ> ls;
  ls.setInputCloud(nans);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  EXPECT_FALSE(ls.getStatus().ok);
  EXPECT_NE(ls.getStatus().message.find("no finite point"), std::string::npos) << ls.getStatus().message;
  EXPECT_TRUE(mesh.polygons.empty());

  auto cloud = torus_cloud<pcl::PointXYZ>(3000);
  pcl::IndicesPtr indices(new pcl::Indices);
  for (int i = 0; i < int(cloud->size()); ++i) indices->push_back(i);
  indices->push_back(int(cloud->size()) + 5);  // out of range
  indices->push_back(-1);
  ls.setInputCloud(cloud);
  ls.setIndices(indices);
  ls.reconstruct(mesh);
  ASSERT_TRUE(ls.getStatus().ok) << ls.getStatus().message;
  EXPECT_EQ(ls.getStatus().skipped_points, 3u);  // the NaN point and the two bad indices
}

std::vector<pcl::Indices> polygons_of(pcl::LevelSetReconstruction<pcl::PointXYZ>& ls,
                                      const pcl::PointCloud<pcl::PointXYZ>::Ptr& cloud) {
  ls.setInputCloud(cloud);
  pcl::PolygonMesh mesh;
  ls.reconstruct(mesh);
  EXPECT_TRUE(ls.getStatus().ok) << ls.getStatus().message;
  std::vector<pcl::Indices> polygons;
  for (const auto& p : mesh.polygons) polygons.push_back(p.vertices);
  return polygons;
}

TEST(PclLevelSetReconstruction, ReusedOrRunTwiceAtOnceGivesWhatEachGivesAlone) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr sphere(new pcl::PointCloud<pcl::PointXYZ>);
  for (const auto& p : lsr::sample_test_shape(lsr::make_test_shape("sphere"), 2000).points) {
    sphere->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  }
  const auto torus = torus_cloud<pcl::PointXYZ>(3000);
  pcl::LevelSetReconstruction<pcl::PointXYZ> a, b;
  const auto sphere_alone = polygons_of(a, sphere);
  const auto torus_alone = polygons_of(b, torus);
  // Reused: the sphere's object on the torus gives the torus's mesh, and back.
  EXPECT_EQ(polygons_of(a, torus), torus_alone);
  EXPECT_EQ(polygons_of(a, sphere), sphere_alone);
  // Two objects on two threads at once.
  std::vector<pcl::Indices> sphere_threaded, torus_threaded;
  std::thread first([&] { sphere_threaded = polygons_of(a, sphere); });
  std::thread second([&] { torus_threaded = polygons_of(b, torus); });
  first.join();
  second.join();
  EXPECT_EQ(sphere_threaded, sphere_alone);
  EXPECT_EQ(torus_threaded, torus_alone);
}

// Every length the setters take is in the cloud's units: the same cloud 1024 times larger (a
// power of two: every coordinate and length scales exactly, and so does the unit box's map)
// with lengths 1024 times larger gives the same mesh, 1024 times larger.
TEST(PclLevelSetReconstruction, LengthsAreInTheCloudsUnits) {
  const auto small = torus_cloud<pcl::PointXYZ>(3000);
  pcl::PointCloud<pcl::PointXYZ>::Ptr large(new pcl::PointCloud<pcl::PointXYZ>(*small));
  for (auto& p : *large) p.getVector3fMap() *= 1024.0f;
  pcl::LevelSetReconstruction<pcl::PointXYZ> a, b;
  a.setResolution(0.1);
  a.setHoleRadius(0.2);
  a.setTolerance(0.05);
  a.setCurvatureWeight(0.01);
  b.setResolution(0.1 * 1024);
  b.setHoleRadius(0.2 * 1024);
  b.setTolerance(0.05 * 1024);
  b.setCurvatureWeight(0.01 * 1024 * 1024);
  const auto polygons = polygons_of(a, small);
  ASSERT_FALSE(polygons.empty());
  EXPECT_EQ(polygons_of(b, large), polygons);
  EXPECT_DOUBLE_EQ(b.getStatus().tolerance, 1024 * a.getStatus().tolerance);
  // The large cloud's lengths on the small cloud: a mesh size wider than the cloud, refused.
  b.setInputCloud(small);
  pcl::PolygonMesh mesh;
  b.reconstruct(mesh);
  EXPECT_FALSE(b.getStatus().ok);
  EXPECT_NE(b.getStatus().message.find("h_min"), std::string::npos) << b.getStatus().message;
}

}  // namespace
