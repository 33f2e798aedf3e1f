// SPDX-License-Identifier: BSD-3-Clause
/// @file openmesh_mesh.cpp
#include "lsrecon/adapters/openmesh_mesh.h"

#include "double_mesh_writer.h"
#include "lsrecon/adapters/file_header_checks.h"
#include "lsrecon/adapters/pcl_mesh.h"
#include "lsrecon/adapters/point_files.h"

#include "lsrecon/adapters/atomic_file.h"
#include "lsrecon/core/errors.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <pcl/conversions.h>
#include <pcl/io/vtk_io.h>
#include <pcl/io/vtk_lib_io.h>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>
#include <OpenMesh/Tools/Smoother/JacobiLaplaceSmootherT.hh>

#include <algorithm>
#include <fstream>
#include <cctype>

namespace lsr::adapters {

TriMesh to_openmesh(const LevelSetMesh<3>& surface, const Points<3>& normals) {
  TriMesh mesh;
  if (!normals.empty()) mesh.request_vertex_normals();  // none given: write none, not zeros
  std::vector<TriMesh::VertexHandle> handles;
  handles.reserve(surface.vertices.size());
  for (std::size_t i = 0; i < surface.vertices.size(); ++i) {
    const Vec<3>& p = surface.vertices[i];
    handles.push_back(mesh.add_vertex(TriMesh::Point(p.x(), p.y(), p.z())));
    if (mesh.has_vertex_normals() && i < normals.size()) {
      mesh.set_normal(handles.back(), TriMesh::Normal(normals[i].x(), normals[i].y(), normals[i].z()));
    }
  }
  for (std::size_t f = 0; f < surface.facets.size(); ++f) {
    const auto& t = surface.facets[f];
    if (!mesh.add_face(handles[t[0]], handles[t[1]], handles[t[2]]).is_valid()) {
      throw Error("OpenMesh refused triangle " + std::to_string(f) + " (the surface is not a manifold there)",
                  "report this input: lsrecon's surfaces are manifold by construction");
    }
  }
  return mesh;
}

void set_distance_to_data(TriMesh& mesh, const std::vector<double>& distance) {
  if (distance.size() != mesh.n_vertices()) throw Error("one distance per vertex expected", "pass ReconstructionResult::distance_to_data");
  OpenMesh::VPropHandleT<double> h;
  if (!mesh.get_property_handle(h, kDistanceProperty)) mesh.add_property(h, kDistanceProperty);
  for (const auto& v : mesh.vertices()) mesh.property(h, v) = distance[std::size_t(v.idx())];
}

std::optional<OpenMesh::VPropHandleT<double>> distance_to_data(const TriMesh& mesh) {
  OpenMesh::VPropHandleT<double> h;
  if (!mesh.get_property_handle(h, kDistanceProperty)) return std::nullopt;
  return h;
}

LevelSetMesh<3> from_openmesh(const TriMesh& mesh) {
  LevelSetMesh<3> out;
  for (const auto& v : mesh.vertices()) {
    const auto& p = mesh.point(v);
    out.vertices.emplace_back(p[0], p[1], p[2]);
  }
  for (const auto& f : mesh.faces()) {
    std::array<Index, 3> tri{};
    int k = 0;
    for (const auto& v : mesh.fv_range(f)) tri[k++] = Index(v.idx());
    out.facets.push_back(tri);
  }
  return out;
}

namespace {

// pcl::PolygonMesh (float, as PCL's own tools write VTK), vertex normals if the mesh has them.
pcl::PolygonMesh to_polygon_mesh(const TriMesh& mesh) {
  const LevelSetMesh<3> m = from_openmesh(mesh);
  Points<3> normals(m.vertices.size(), Vec<3>::Zero());
  if (mesh.has_vertex_normals()) {
    for (const auto& v : mesh.vertices()) normals[std::size_t(v.idx())] = Vec<3>(mesh.normal(v)[0], mesh.normal(v)[1], mesh.normal(v)[2]);
  }
  pcl::PolygonMesh out;
  pcl::toPCLPointCloud2(normal_cloud<3>(m.vertices, normals), out.cloud);
  out.polygons = polygons_from_triangles(m.facets);
  return out;
}

}  // namespace

TriMesh read_mesh_file(const std::string& path) {
  const std::string ext = file_extension(path);
  if (!has_role(ext, FileRole::mesh_output)) {
    throw Error("cannot read a mesh from '" + path + "'", "use a mesh file ending in " + extensions(FileRole::mesh_output));
  }
  if (!std::ifstream(path)) throw Error("cannot open " + path, "check the path");
  TriMesh mesh;
  if (ext == "vtk") {
    pcl::PolygonMesh polygons;
    if (pcl::io::loadPolygonFileVTK(path, polygons) == 0) throw Error("cannot read the mesh " + path, "check the file");
    LevelSetMesh<3> triangles;
    triangles_from_polygon_mesh(polygons, triangles.vertices, triangles.facets);
    return to_openmesh(triangles, {});
  }
  check_declared_size(path);
  if (!OpenMesh::IO::read_mesh(mesh, path)) throw Error("cannot read the mesh " + path, "check the file");
  return mesh;
}

void write_mesh_file(const TriMesh& mesh, const std::string& path) {
  const std::string ext = file_extension(path);
  if (!has_role(ext, FileRole::mesh_output)) {
    throw Error("cannot write a mesh to '" + path + "'", "use an output ending in " + extensions(FileRole::mesh_output));
  }
  write_file_atomically(path, [&](const std::string& temporary) {
    const bool written = ext == "stl"   ? OpenMesh::IO::write_mesh(mesh, temporary, OpenMesh::IO::Options::Binary)
                         : ext == "vtk" ? pcl::io::saveVTKFile(temporary, to_polygon_mesh(mesh), 9) == 0
                                        : write_double_precision(mesh, ext, temporary);
    if (!written) throw Error("writing " + path + " failed", "check that the folder exists, is writable and has space");
  });
}

std::size_t decimate(TriMesh& mesh, std::size_t target_faces) {
  using Decimater = OpenMesh::Decimater::DecimaterT<TriMesh>;
  using Quadric = OpenMesh::Decimater::ModQuadricT<TriMesh>::Handle;
  using NoFlip = OpenMesh::Decimater::ModNormalFlippingT<TriMesh>::Handle;
  if (!mesh.has_face_normals()) mesh.request_face_normals();
  mesh.update_face_normals();
  Decimater decimater(mesh);
  Quadric quadric;
  NoFlip no_flip;
  decimater.add(quadric);
  decimater.add(no_flip);
  decimater.initialize();
  decimater.decimate_to_faces(0, target_faces);
  mesh.garbage_collection();
  if (mesh.has_vertex_normals()) mesh.update_vertex_normals();
  return mesh.n_faces();
}

void smooth(TriMesh& mesh, unsigned iterations) {
  if (iterations == 0) return;
  if (!mesh.has_face_normals()) mesh.request_face_normals();
  if (!mesh.has_vertex_normals()) mesh.request_vertex_normals();
  mesh.update_normals();
  OpenMesh::Smoother::JacobiLaplaceSmootherT<TriMesh> smoother(mesh);
  smoother.initialize(OpenMesh::Smoother::SmootherT<TriMesh>::Tangential_and_Normal,
                      OpenMesh::Smoother::SmootherT<TriMesh>::C1);
  smoother.smooth(iterations);
  mesh.update_normals();
}

}  // namespace lsr::adapters
