#pragma once
/// \file
/// The three kinds of separating-axis candidate between two convex
/// polyhedra: a face normal of A, a face normal of B, and the cross product
/// of an edge of each. The generator's SAT and the brute-force oracle both
/// name their axes with it; it carries no rule of either.

namespace mfz {

enum class AxisKind { face_a, face_b, edge_edge };

inline const char* axis_kind_name(AxisKind kind) {
  switch (kind) {
    case AxisKind::face_a: return "face of A";
    case AxisKind::face_b: return "face of B";
    case AxisKind::edge_edge: return "edge of A x edge of B";
  }
  return "?";
}

}  // namespace mfz
