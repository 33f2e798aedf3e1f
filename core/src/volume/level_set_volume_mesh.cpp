// SPDX-License-Identifier: BSD-3-Clause
#include "lsrecon/core/level_set_volume_mesh.h"

#include "lsrecon/core/errors.h"
#include "lsrecon/core/types.h"
#include "volume/simplex_angles.h"
#include "volume/sliver_removal.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace lsr {
namespace {

bool negative(double u) { return u < 0.0; }  // as the extraction decides: 0 is outside

std::uint64_t edge_key(Index a, Index b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

template <int D>
class Splitter {
 public:
  Splitter(const SimplexMesh<D>& mesh, const std::vector<double>& u, const LevelSetMesh<D>& surface)
      : mesh_(mesh), u_(u) {
    const Index nv = Index(mesh.vertices.size());
    out_.vertices = mesh.vertices;
    out_.vertices.insert(out_.vertices.end(), surface.vertices.begin(), surface.vertices.end());
    out_.interface_offset = nv;
    // Orientation is decided on the positions the cut was made at, so that a vertex moved
    // since (projection) cannot hide an inverted simplex from the quality check.
    cut_ = mesh.vertices;
    for (std::size_t i = 0; i < surface.sources.size(); ++i) {
      const EdgePoint& e = surface.sources[i];
      edge_.emplace(edge_key(e.a, e.b), nv + Index(i));
      cut_.push_back(edge_point_position(mesh, e));
    }
    for (auto f : surface.facets) {
      for (Index& v : f) v += nv;
      out_.interface.push_back(f);
    }
  }

  void split(Index s);
  VolumeMesh<D> take();

 private:
  void untangle();

  using Simplex = std::array<Index, D + 1>;

  Index edge_point(Index a, Index b) const {
    const auto it = edge_.find(edge_key(a, b));
    if (it == edge_.end()) {
      throw InvalidInput("the surface has no vertex on crossed mesh edge (" + std::to_string(a) + ", " +
                             std::to_string(b) + ")",
                         "pass the surface extracted from the same values");
    }
    return it->second;
  }

  void emit(Simplex s, int region) {
    if (signed_measure_of<D>(cut_, s) < 0.0) std::swap(s[0], s[1]);
    out_.simplices.push_back(s);
    out_.regions.push_back(region);
  }

  void split_prism(std::array<Index, 3> b, std::array<Index, 3> t, std::array<bool, 3> rising, int region);  // 3D
  // Quad (b_i, b_j, t_j, t_i) of a prism in a face of the box mesh: cut through its smallest
  // vertex id, as the simplex on the other side of the face cuts it.
  static bool rising_by_id(Index bi, Index bj, Index ti, Index tj) {
    return std::min(bi, tj) < std::min(bj, ti);
  }

  const SimplexMesh<D>& mesh_;
  const std::vector<double>& u_;
  std::unordered_map<std::uint64_t, Index> edge_;
  Points<D> cut_;
  VolumeMesh<D> out_;
};

// The prism (b0 b1 b2 | t0 t1 t2), b_i below t_i, whose quad i = (b_i, b_{i+1}, t_{i+1}, t_i) is
// cut along b_i-t_{i+1} when rising[i], else along b_{i+1}-t_i. Three tetrahedra from a vertex
// where two cuts meet (Dompierre et al.); a centre vertex when the cuts turn in a cycle.
template <>
void Splitter<3>::split_prism(std::array<Index, 3> b, std::array<Index, 3> t, std::array<bool, 3> rising, int region) {
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i < 3; ++i) {
      if (!rising[i] || rising[(i + 2) % 3]) continue;  // b_i is where two cuts meet
      std::rotate(b.begin(), b.begin() + i, b.end());
      std::rotate(t.begin(), t.begin() + i, t.end());
      const bool one_five = rising[(i + 1) % 3];  // quad (b1 b2 t2 t1) cut along b1-t2
      if (one_five) {
        emit({b[0], b[1], b[2], t[2]}, region);
        emit({b[0], b[1], t[2], t[1]}, region);
      } else {
        emit({b[0], b[1], b[2], t[1]}, region);
        emit({b[0], t[1], b[2], t[2]}, region);
      }
      emit({b[0], t[1], t[2], t[0]}, region);
      return;
    }
    // Seen upside down, a top vertex where two cuts meet is a bottom one.
    std::swap(b, t);
    for (bool& r : rising) r = !r;
  }
  // A cycle: every face cut as given, coned to the centre.
  const Index c = Index(out_.vertices.size());
  Vec<3> centre = Vec<3>::Zero(), cut_centre = Vec<3>::Zero();
  for (int k = 0; k < 3; ++k) {
    centre += (out_.vertices[b[k]] + out_.vertices[t[k]]) / 6.0;
    cut_centre += (cut_[b[k]] + cut_[t[k]]) / 6.0;
  }
  out_.vertices.push_back(centre);
  cut_.push_back(cut_centre);
  emit({b[0], b[1], b[2], c}, region);
  emit({t[0], t[1], t[2], c}, region);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (rising[i]) {
      emit({b[i], b[j], t[j], c}, region);
      emit({b[i], t[j], t[i], c}, region);
    } else {
      emit({b[i], b[j], t[i], c}, region);
      emit({b[j], t[j], t[i], c}, region);
    }
  }
}

// A facet of a positively oriented simplex, oriented outwards: the vertices but `opposite`,
// in an order of the right parity.
template <int D>
std::array<Index, D> outward_facet(const std::array<Index, D + 1>& s, int opposite) {
  std::array<Index, D> f{};
  for (int k = 0, n = 0; k <= D; ++k) {
    if (k != opposite) f[n++] = s[k];
  }
  // The remaining vertices in order face outwards when the removed one was at an even
  // position (k = 0: (s1 s2 s3) faces away from s0), inwards otherwise.
  if (opposite % 2 == 1) std::swap(f[0], f[1]);
  return f;
}

// Vertices that moved since the cut (the surface's projection onto a fit) can flatten a thin
// simplex or turn it inside out: such vertices go back towards where the cut put them, halving
// the move until no simplex they are in is flat (at the cut positions every simplex is
// positive, by construction; one flat there is the smoothing's business).
template <int D>
void Splitter<D>::untangle() {
  const Index first_movable = out_.interface_offset;
  const double flat = kFlatMeasure / double(out_.simplices.size());  // the box's measure is 1
  std::vector<char> pulled(out_.vertices.size(), 0);
  // After kHalvings rounds the vertices still in a flat simplex go to their cut positions; that
  // can flatten a simplex one of them shares with a vertex still part-way, so the rounds go on
  // (each puts at least one vertex back for good) until no moved vertex is in a flat simplex.
  constexpr int kHalvings = 10;
  for (int round = 0;; ++round) {
    std::vector<char> move(out_.vertices.size(), 0);
    bool any = false;
    for (const auto& s : out_.simplices) {
      if (signed_measure_of<D>(out_.vertices, s) > flat) continue;
      for (Index v : s) {
        if (v >= first_movable && out_.vertices[v] != cut_[v]) move[v] = pulled[v] = 1;
        any = any || move[v];
      }
    }
    if (!any) break;
    for (std::size_t v = 0; v < move.size(); ++v) {
      if (!move[v]) continue;
      out_.vertices[v] = round >= kHalvings ? cut_[v] : Vec<D>(cut_[v] + 0.5 * (out_.vertices[v] - cut_[v]));
    }
  }
  out_.pulled_back = std::size_t(std::count(pulled.begin(), pulled.end(), char(1)));
}

template <int D>
VolumeMesh<D> Splitter<D>::take() {
  untangle();
  // Facets with every vertex on one wall of the unit box (the mesh's own boundary).
  for (const auto& s : out_.simplices) {
    for (int k = 0; k <= D; ++k) {
      const std::array<Index, D> f = outward_facet<D>(s, k);
      for (int axis = 0; axis < D; ++axis) {
        const double w = out_.vertices[f[0]][axis];
        if (w != 0.0 && w != 1.0) continue;
        bool on = true;
        for (Index v : f) on = on && out_.vertices[v][axis] == w;
        if (on) out_.walls.push_back(f);
      }
    }
  }
  return std::move(out_);
}

template <>
void Splitter<2>::split(Index s) {
  const auto& v = mesh_.simplices[s];
  int negatives = 0;
  for (int k = 0; k < 3; ++k) negatives += negative(u_[v[k]]) ? 1 : 0;
  if (negatives == 0 || negatives == 3) {
    emit(v, negatives == 3 ? kInsideRegion : kOutsideRegion);
    return;
  }
  // The lone vertex L (the one on its side) and the other two, P and Q.
  int l = 0;
  for (int k = 0; k < 3; ++k) {
    if (negative(u_[v[k]]) == (negatives == 1)) l = k;
  }
  const Index L = v[l], P = v[(l + 1) % 3], Q = v[(l + 2) % 3];
  const Index e1 = edge_point(L, P), e2 = edge_point(L, Q);
  const int lone = negative(u_[L]) ? kInsideRegion : kOutsideRegion;
  const int other = lone == kInsideRegion ? kOutsideRegion : kInsideRegion;
  emit({L, e1, e2}, lone);
  // The quad (e1, P, Q, e2) lies inside this triangle: either diagonal conforms; the shorter.
  if ((cut_[e1] - cut_[Q]).squaredNorm() <= (cut_[e2] - cut_[P]).squaredNorm()) {
    emit({e1, P, Q}, other);
    emit({e1, Q, e2}, other);
  } else {
    emit({e1, P, e2}, other);
    emit({P, Q, e2}, other);
  }
}

template <>
void Splitter<3>::split(Index s) {
  const auto& v = mesh_.simplices[s];
  std::array<Index, 4> neg{}, pos{};
  int nn = 0, np = 0;
  for (int k = 0; k < 4; ++k) {
    if (negative(u_[v[k]])) {
      neg[nn++] = v[k];
    } else {
      pos[np++] = v[k];
    }
  }
  if (nn == 0 || nn == 4) {
    emit(v, nn == 4 ? kInsideRegion : kOutsideRegion);
    return;
  }
  if (nn == 1 || nn == 3) {
    // A corner tetrahedron at the lone vertex and a prism between the cut and the far face.
    const Index L = nn == 1 ? neg[0] : pos[0];
    const std::array<Index, 3> far = nn == 1 ? std::array<Index, 3>{pos[0], pos[1], pos[2]}
                                             : std::array<Index, 3>{neg[0], neg[1], neg[2]};
    const std::array<Index, 3> cut = {edge_point(L, far[0]), edge_point(L, far[1]), edge_point(L, far[2])};
    const int lone = nn == 1 ? kInsideRegion : kOutsideRegion;
    emit({L, cut[0], cut[1], cut[2]}, lone);
    std::array<bool, 3> rising{};
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      rising[i] = rising_by_id(cut[i], cut[j], far[i], far[j]);
    }
    split_prism(cut, far, rising, lone == kInsideRegion ? kOutsideRegion : kInsideRegion);
    return;
  }
  // Two and two: a prism on each side of the interface quad (a b d c), where a = (n1 p1),
  // b = (n1 p2), c = (n2 p1), d = (n2 p2). The surface cut that quad (in its order
  // a, b, d, c) along a-d or b-c.
  const Index n1 = neg[0], n2 = neg[1], p1 = pos[0], p2 = pos[1];
  const Index a = edge_point(n1, p1), b = edge_point(n1, p2), c = edge_point(n2, p1), d = edge_point(n2, p2);
  const bool along_ad = split_quad_along_02<3>(cut_[a], cut_[b], cut_[d], cut_[c]);
  // Inside: (n1 a b | n2 c d); quads (n1 a c n2), (a b d c), (b n1 n2 d).
  split_prism({n1, a, b}, {n2, c, d}, {rising_by_id(n1, a, n2, c), along_ad, rising_by_id(b, n1, d, n2)}, kInsideRegion);
  // Outside: (p1 a c | p2 b d); quads (p1 a b p2), (a c d b), (c p1 p2 d).
  split_prism({p1, a, c}, {p2, b, d}, {rising_by_id(p1, a, p2, b), along_ad, rising_by_id(c, p1, d, p2)},
              kOutsideRegion);
}

}  // namespace

template <int D>
VolumeMesh<D> split_along_level_set(const SimplexMesh<D>& mesh, const std::vector<double>& values,
                                    const LevelSetMesh<D>& surface) {
  if (values.size() != mesh.vertices.size() || surface.sources.size() != surface.vertices.size()) {
    throw InvalidInput("values or surface do not match the mesh", "pass the mesh, its nodal values and their surface");
  }
  Splitter<D> splitter(mesh, values, surface);
  for (Index s = 0; s < Index(mesh.simplices.size()); ++s) splitter.split(s);
  VolumeMesh<D> out = splitter.take();
  smooth_near_slivers(out, 3);
  return out;
}

template <int D>
VolumeMeshQuality volume_mesh_quality(const VolumeMesh<D>& mesh) {
  VolumeMeshQuality q;
  std::vector<double> angles;
  angles.reserve(mesh.simplices.size() * (D == 2 ? 3 : 6));
  std::size_t small = 0;
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < mesh.simplices.size(); ++s) {
    const double m = signed_measure_of<D>(mesh.vertices, mesh.simplices[s]);
    if (m <= 0.0) ++q.inverted;
    smallest = std::min(smallest, m);
    if (mesh.regions[s] == kInsideRegion) {
      q.inside_measure += m;
      ++q.inside_simplices;
    } else {
      q.outside_measure += m;
      ++q.outside_simplices;
    }
    const auto these = angles_of<D>(mesh.vertices, mesh.simplices[s]);
    angles.insert(angles.end(), these.begin(), these.end());
    if (*std::min_element(these.begin(), these.end()) < 5.0 * kPi / 180.0) ++small;
  }
  if (!mesh.simplices.empty()) {
    q.min_relative_measure = smallest * double(mesh.simplices.size()) / (q.inside_measure + q.outside_measure);
  }
  q.small_angle_fraction = mesh.simplices.empty() ? 0.0 : double(small) / double(mesh.simplices.size());
  if (!angles.empty()) {
    const auto middle = angles.begin() + std::ptrdiff_t(angles.size() / 2);
    std::nth_element(angles.begin(), middle, angles.end());
    q.median_angle_degrees = *middle * 180.0 / kPi;
    q.min_angle_degrees = *std::min_element(angles.begin(), angles.end()) * 180.0 / kPi;
  }
  return q;
}

template VolumeMesh<2> split_along_level_set<2>(const SimplexMesh<2>&, const std::vector<double>&, const LevelSetMesh<2>&);
template VolumeMesh<3> split_along_level_set<3>(const SimplexMesh<3>&, const std::vector<double>&, const LevelSetMesh<3>&);
template VolumeMeshQuality volume_mesh_quality<2>(const VolumeMesh<2>&);
template VolumeMeshQuality volume_mesh_quality<3>(const VolumeMesh<3>&);

}  // namespace lsr
