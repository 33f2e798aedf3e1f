// SPDX-License-Identifier: BSD-3-Clause
/// @file facet_intersection.cpp
/// @brief Closed triangles meet when an edge of one meets the other (not coplanar: A and B
/// meet in a segment of the line of their planes, whose ends lie on their edges), or, coplanar,
/// when their projections onto a coordinate plane meet. Every branch reads signs of exact
/// predicates; the boxes' comparisons are exact as well.
#include "geometry/facet_intersection.h"

#include "geometry/exact_predicates.h"

#include <algorithm>
#include <cmath>

namespace lsr::detail {
namespace {

// A coplanar configuration seen along a coordinate axis: exact, the axis being one along which
// the plane is not seen edge-on.
struct Flat {
  double x, y;
};

Flat drop(const Vec<3>& p, int axis) {
  if (axis == 0) return {p[1], p[2]};
  if (axis == 1) return {p[2], p[0]};
  return {p[0], p[1]};
}

int orient(const Flat& a, const Flat& b, const Flat& c) { return orient2d(a.x, a.y, b.x, b.y, c.x, c.y); }

// An axis along which triangle abc projects to a triangle, -1 when its corners are collinear.
int projection_axis(const Vec<3>& a, const Vec<3>& b, const Vec<3>& c) {
  const Vec<3> n = (b - a).cross(c - a).cwiseAbs();
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return n[i] > n[j]; });
  for (int axis : order) {
    if (orient(drop(a, axis), drop(b, axis), drop(c, axis)) != 0) return axis;
  }
  return -1;
}

template <int D>
bool boxes_overlap(std::initializer_list<const Vec<D>*> a, std::initializer_list<const Vec<D>*> b) {
  for (int k = 0; k < D; ++k) {
    double a_lo = (**a.begin())[k], a_hi = a_lo, b_lo = (**b.begin())[k], b_hi = b_lo;
    for (const Vec<D>* p : a) a_lo = std::min(a_lo, (*p)[k]), a_hi = std::max(a_hi, (*p)[k]);
    for (const Vec<D>* p : b) b_lo = std::min(b_lo, (*p)[k]), b_hi = std::max(b_hi, (*p)[k]);
    if (a_hi < b_lo || b_hi < a_lo) return false;
  }
  return true;
}

// r on the closed segment pq, given that it is on its line.
bool within(const Flat& p, const Flat& q, const Flat& r) {
  return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
}

bool segments_meet(const Flat& p, const Flat& q, const Flat& r, const Flat& s) {
  const int o1 = orient(p, q, r), o2 = orient(p, q, s), o3 = orient(r, s, p), o4 = orient(r, s, q);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within(p, q, r)) || (o2 == 0 && within(p, q, s)) || (o3 == 0 && within(r, s, p)) ||
         (o4 == 0 && within(r, s, q));
}

// p in the closed triangle abc of orientation `turn` (non-zero).
bool inside(const Flat& a, const Flat& b, const Flat& c, int turn, const Flat& p) {
  return orient(a, b, p) * turn >= 0 && orient(b, c, p) * turn >= 0 && orient(c, a, p) * turn >= 0;
}

// Closed coplanar triangles, seen along `axis` (along which a projects to a triangle).
bool coplanar_triangles_meet(const std::array<const Vec<3>*, 3>& a, const std::array<const Vec<3>*, 3>& b, int axis) {
  Flat fa[3], fb[3];
  for (int k = 0; k < 3; ++k) fa[k] = drop(*a[k], axis), fb[k] = drop(*b[k], axis);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (segments_meet(fa[i], fa[(i + 1) % 3], fb[j], fb[(j + 1) % 3])) return true;
    }
  }
  const int turn_a = orient(fa[0], fa[1], fa[2]), turn_b = orient(fb[0], fb[1], fb[2]);
  if (inside(fa[0], fa[1], fa[2], turn_a, fb[0])) return true;
  return turn_b != 0 && inside(fb[0], fb[1], fb[2], turn_b, fa[0]);
}

// The closed segment pq and the closed triangle abc.
bool segment_meets_triangle(const Vec<3>& p, const Vec<3>& q, const Vec<3>& a, const Vec<3>& b, const Vec<3>& c) {
  if (!boxes_overlap<3>({&p, &q}, {&a, &b, &c})) return false;
  const int op = orient3d(a, b, c, p), oq = orient3d(a, b, c, q);
  if (op * oq > 0) return false;
  if (op == 0 && oq == 0) {
    const int axis = projection_axis(a, b, c);
    if (axis < 0) return true;  // a degenerate triangle
    const Flat fa = drop(a, axis), fb = drop(b, axis), fc = drop(c, axis), fp = drop(p, axis), fq = drop(q, axis);
    const int turn = orient(fa, fb, fc);
    return inside(fa, fb, fc, turn, fp) || segments_meet(fp, fq, fa, fb) || segments_meet(fp, fq, fb, fc) ||
           segments_meet(fp, fq, fc, fa);
  }
  // The line pq crosses the plane within the segment: inside the triangle when it passes no
  // edge on the outer side (Pluecker signs all of one sign or zero).
  const int s1 = orient3d(p, q, a, b), s2 = orient3d(p, q, b, c), s3 = orient3d(p, q, c, a);
  return !((s1 > 0 || s2 > 0 || s3 > 0) && (s1 < 0 || s2 < 0 || s3 < 0));
}

bool triangles_meet(const std::array<const Vec<3>*, 3>& a, const std::array<const Vec<3>*, 3>& b) {
  if (!boxes_overlap<3>({a[0], a[1], a[2]}, {b[0], b[1], b[2]})) return false;
  int ob[3], oa[3];
  for (int k = 0; k < 3; ++k) ob[k] = orient3d(*a[0], *a[1], *a[2], *b[k]);
  if ((ob[0] > 0 && ob[1] > 0 && ob[2] > 0) || (ob[0] < 0 && ob[1] < 0 && ob[2] < 0)) return false;
  if (ob[0] == 0 && ob[1] == 0 && ob[2] == 0) {
    const int axis = projection_axis(*a[0], *a[1], *a[2]);
    return axis < 0 || coplanar_triangles_meet(a, b, axis);
  }
  for (int k = 0; k < 3; ++k) oa[k] = orient3d(*b[0], *b[1], *b[2], *a[k]);
  if ((oa[0] > 0 && oa[1] > 0 && oa[2] > 0) || (oa[0] < 0 && oa[1] < 0 && oa[2] < 0)) return false;
  for (int k = 0; k < 3; ++k) {
    if (segment_meets_triangle(*a[k], *a[(k + 1) % 3], *b[0], *b[1], *b[2])) return true;
    if (segment_meets_triangle(*b[k], *b[(k + 1) % 3], *a[0], *a[1], *a[2])) return true;
  }
  return false;
}

// Triangles (p, q, r) and (q, p, s) sharing the edge pq meet elsewhere only folded onto each
// other: coplanar, r and s on one side of pq. r and s on opposite sides of the edge's normal
// plane decides most pairs in doubles: (r-p).(s-p) |e|^2 - ((r-p).e)((s-p).e) is a degree-4
// form whose rounding error is below 32 eps of its terms' magnitude (two dot products of 5
// eps each, their products and the difference).
bool folded(const Vec<3>& p, const Vec<3>& q, const Vec<3>& r, const Vec<3>& s) {
  const Vec<3> e = q - p, rp = r - p, sp = s - p;
  const double across = rp.dot(sp) * e.dot(e) - rp.dot(e) * sp.dot(e);
  const double magnitude = rp.cwiseAbs().dot(sp.cwiseAbs()) * e.cwiseAbs().dot(e.cwiseAbs()) +
                           rp.cwiseAbs().dot(e.cwiseAbs()) * sp.cwiseAbs().dot(e.cwiseAbs());
  if (across < -32.0 * predicates::kEpsilon * magnitude) return false;
  if (orient3d(p, q, r, s) != 0) return false;
  const int axis = projection_axis(p, q, r);
  if (axis < 0) return true;
  const int side_r = orient(drop(p, axis), drop(q, axis), drop(r, axis)), side_s = orient(drop(p, axis), drop(q, axis), drop(s, axis));
  return side_s == 0 || side_r == side_s;
}

// With b in the plane of triangle (v, a1, a2): the ray from v through b enters the triangle.
bool ray_enters(const Vec<3>& v, const Vec<3>& b, const Vec<3>& a1, const Vec<3>& a2) {
  const int axis = projection_axis(v, a1, a2);
  if (axis < 0) return true;
  const Flat fv = drop(v, axis), f1 = drop(a1, axis), f2 = drop(a2, axis), fb = drop(b, axis);
  const int turn = orient(fv, f1, f2), o1 = orient(fv, f1, fb), o2 = orient(fv, fb, f2);
  if (o1 == -turn || o2 == -turn) return false;
  if (o1 == 0 && o2 == 0) return true;  // b = v: a degenerate triangle
  if (o1 == 0) return dot_sign<3>(v, a1, b) > 0;
  if (o2 == 0) return dot_sign<3>(v, a2, b) > 0;
  return true;
}

// Triangles (v, a1, a2) and (v, b1, b2) sharing only v: their intersection, a convex set
// holding v, reaches farther than v along a segment that ends on an edge: an opposite edge
// (a1 a2 or b1 b2) meets the other triangle, or an edge at v lies in the other's plane and
// angle.
bool meet_beyond_vertex(const Vec<3>& v, const Vec<3>& a1, const Vec<3>& a2, const Vec<3>& b1, const Vec<3>& b2) {
  const int o1 = orient3d(v, a1, a2, b1), o2 = orient3d(v, a1, a2, b2);
  if (o1 * o2 > 0) return false;
  const int o3 = orient3d(v, b1, b2, a1), o4 = orient3d(v, b1, b2, a2);
  if (o3 * o4 > 0) return false;
  return segment_meets_triangle(a1, a2, v, b1, b2) || segment_meets_triangle(b1, b2, v, a1, a2) ||
         (o1 == 0 && ray_enters(v, b1, a1, a2)) || (o2 == 0 && ray_enters(v, b2, a1, a2)) ||
         (o3 == 0 && ray_enters(v, a1, b1, b2)) || (o4 == 0 && ray_enters(v, a2, b1, b2));
}

}  // namespace

bool facets_intersect(const Points<3>& x, const std::array<Index, 3>& f, const std::array<Index, 3>& g) {
  // Where g's corners are in f (index), -1 when not.
  int at[3], shared = 0;
  for (int j = 0; j < 3; ++j) {
    at[j] = -1;
    for (int i = 0; i < 3; ++i) {
      if (g[std::size_t(j)] == f[std::size_t(i)]) at[j] = i;
    }
    shared += at[j] >= 0 ? 1 : 0;
  }
  const auto X = [&](Index v) -> const Vec<3>& { return x[std::size_t(v)]; };
  if (shared == 3) return true;  // the same triangle twice
  if (shared == 0) return triangles_meet({&X(f[0]), &X(f[1]), &X(f[2])}, {&X(g[0]), &X(g[1]), &X(g[2])});
  if (shared == 2) {
    const int lone_g = at[0] < 0 ? 0 : (at[1] < 0 ? 1 : 2);
    const int i0 = at[(lone_g + 1) % 3], i1 = at[(lone_g + 2) % 3];
    const int lone_f = 3 - i0 - i1;
    return folded(X(f[std::size_t(i0)]), X(f[std::size_t(i1)]), X(f[std::size_t(lone_f)]), X(g[std::size_t(lone_g)]));
  }
  const int in_g = at[0] >= 0 ? 0 : (at[1] >= 0 ? 1 : 2), in_f = at[in_g];
  return meet_beyond_vertex(X(f[std::size_t(in_f)]), X(f[std::size_t((in_f + 1) % 3)]), X(f[std::size_t((in_f + 2) % 3)]),
                            X(g[std::size_t((in_g + 1) % 3)]), X(g[std::size_t((in_g + 2) % 3)]));
}

bool facets_intersect(const Points<2>& x, const std::array<Index, 2>& f, const std::array<Index, 2>& g) {
  const auto X = [&](Index v) -> const Vec<2>& { return x[std::size_t(v)]; };
  const bool same0 = f[0] == g[0] || f[0] == g[1], same1 = f[1] == g[0] || f[1] == g[1];
  if (same0 && same1) return true;  // the same segment twice
  if (same0 || same1) {
    // (v, p) and (v, q) meet beyond v when they run along one ray.
    const Index v = same0 ? f[0] : f[1], p = same0 ? f[1] : f[0], q = g[0] == v ? g[1] : g[0];
    return orient2d(X(v), X(p), X(q)) == 0 && dot_sign<2>(X(v), X(p), X(q)) > 0;
  }
  if (!boxes_overlap<2>({&X(f[0]), &X(f[1])}, {&X(g[0]), &X(g[1])})) return false;
  const auto flat = [&](Index v) { return Flat{X(v)[0], X(v)[1]}; };
  return segments_meet(flat(f[0]), flat(f[1]), flat(g[0]), flat(g[1]));
}

}  // namespace lsr::detail
