// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A mesh faired by several processes, none of which holds it whole: the mesh a process gives the library is its
// part (its own faces and rings of faces around them), each vertex and face is one process's own, and a measure
// of the whole mesh is made of the own ones' -- sums and maxima over the processes, samples gathered for an order
// statistic -- with the values of the vertices a process holds but does not own brought from their owners
// (refresh) wherever a measure reads a neighbour. Process_part is what the caller (the distributed program)
// provides; Part_view is the same seen in the numbering the run works in (Locality_ordering.h). A run on one
// process has none: every vertex and face its own, and the exchanges do nothing.

#ifndef CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_PROCESS_PART_H
#define CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_PROCESS_PART_H

#include <CGAL/Anisotropic_fairing/internal/mesh/Locality_ordering.h>
#include <CGAL/Anisotropic_fairing/internal/types/Control_matrix.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Anisotropic_fairing {
namespace internal {

/// The caller's side, in the numbering of the mesh it gave the library (its vertices' and faces' order).
class Process_part
{
public:
  virtual ~Process_part() = default;
  virtual std::int64_t global_vertex(std::size_t v) const = 0;   // vertex v's number in the whole mesh
  virtual std::int64_t global_face(std::size_t f) const = 0;     // face f's
  virtual int vertex_owner(std::size_t v) const = 0;   // the process owning vertex v
  virtual int face_owner(std::size_t f) const = 0;     // the process owning face f
  virtual int rank() const = 0;                      // this process
  /// the owners' values of the vertices this process holds but does not own (`columns` doubles per vertex,
  /// vertex v's at values + v * columns)
  virtual void refresh(double* values, std::size_t columns) const = 0;
  /// the least of every process's values of each vertex, at its owner (the other processes' rows unchanged)
  virtual void minimum_at_owners(double* values, std::size_t columns) const = 0;
  /// over the processes, in place
  virtual void sum(double* values, std::size_t count) const = 0;
  virtual void maximum(double* values, std::size_t count) const = 0;
  /// every process's `values`, one after the other in the order of the processes (the same on each)
  virtual std::vector<double> gathered(const std::vector<double>& values) const = 0;
};

/// A Process_part in the run's numbering (row i: the caller's vertex old_of_new_vertex[i]; face f: the caller's
/// face old_of_new_face[f]), or the whole mesh (no part).
class Part_view
{
public:
  Part_view() = default;
  Part_view(const Process_part* part, const Locality_ordering& ordering) : part_(part)
  {
    if(!part) return;
    caller_ = ordering.old_of_new_vertex;
    own_vertex_.resize(caller_.size());
    vertex_owner_.resize(caller_.size());
    for(std::size_t i = 0; i < caller_.size(); ++i)
    {
      vertex_owner_[i] = part->vertex_owner(std::size_t(caller_[i]));
      own_vertex_[i] = vertex_owner_[i] == part->rank();
    }
    const std::vector<std::size_t>& faces = ordering.old_of_new_face;
    caller_face_ = faces;
    face_owner_.resize(faces.size());
    for(std::size_t f = 0; f < faces.size(); ++f) face_owner_[f] = part->face_owner(faces[f]);
  }

  bool whole() const { return part_ == nullptr; }
  int rank() const { return part_ ? part_->rank() : 0; }
  int vertex_owner(std::size_t i) const { return part_ ? vertex_owner_[i] : 0; }
  std::int64_t global_vertex(std::size_t i) const
  {
    return part_ ? part_->global_vertex(std::size_t(caller_[i])) : std::int64_t(i);
  }
  /// face f's number in the whole mesh (f: the run's numbering; `caller`: the caller's)
  std::int64_t global_face(std::size_t f, bool caller = false) const
  {
    return !part_ ? std::int64_t(f) : part_->global_face(caller ? f : caller_face_[f]);
  }
  int face_owner(std::size_t f) const { return part_ ? face_owner_[f] : 0; }
  bool owns_vertex(std::size_t i) const { return !part_ || (i < own_vertex_.size() && own_vertex_[i]); }
  bool owns_face(std::size_t f) const { return !part_ || (f < face_owner_.size() && face_owner_[f] == part_->rank()); }
  /// edge (f, g) of two real faces is counted once over the processes: by the owner of the one with the lower owner
  bool counts_edge(std::size_t f, std::size_t g) const
  {
    if(!part_) return true;
    const int a = face_owner_[f], b = face_owner_[g];
    return (a < b ? a : b) == part_->rank();
  }

  /// rows 0 .. n-1 of `values` (`columns` doubles per row, row-major): the owners' values into the rows not owned
  void refresh(double* values, std::size_t columns) const
  {
    if(!part_) return;
    std::vector<double> caller(caller_.size() * columns);
    for(std::size_t i = 0; i < caller_.size(); ++i)
      std::copy_n(values + i * columns, columns, caller.data() + std::size_t(caller_[i]) * columns);
    part_->refresh(caller.data(), columns);
    for(std::size_t i = 0; i < caller_.size(); ++i)
      if(!own_vertex_[i])
        std::copy_n(caller.data() + std::size_t(caller_[i]) * columns, columns, values + i * columns);
  }
  void refresh(std::vector<double>& field) const { refresh(field.data(), 1); }
  void refresh(Control_matrix& X) const { refresh(X.data(), std::size_t(X.cols())); }
  /// one value per row: the least of every process's value of each vertex, at its owner
  void minimum_at_owners(std::vector<double>& field) const
  {
    if(!part_) return;
    std::vector<double> caller(caller_.size());
    for(std::size_t i = 0; i < caller_.size(); ++i) caller[std::size_t(caller_[i])] = field[i];
    part_->minimum_at_owners(caller.data(), 1);
    for(std::size_t i = 0; i < caller_.size(); ++i) field[i] = caller[std::size_t(caller_[i])];
  }

  double sum(double x) const
  {
    if(part_) part_->sum(&x, 1);
    return x;
  }
  void sum(std::vector<double>& v) const
  {
    if(part_ && !v.empty()) part_->sum(v.data(), v.size());
  }
  double maximum(double x) const
  {
    if(part_) part_->maximum(&x, 1);
    return x;
  }
  std::size_t count(std::size_t local) const { return std::size_t(sum(double(local)) + 0.5); }
  /// `rows` of this process's own vertices only
  std::vector<bool> own(std::vector<bool> rows) const
  {
    for(std::size_t i = 0; i < rows.size() && part_; ++i) rows[i] = rows[i] && owns_vertex(i);
    return rows;
  }
  /// every process's `values` (the whole mesh's, when each gives its own vertices')
  std::vector<double> gathered(std::vector<double> values) const { return part_ ? part_->gathered(values) : values; }

private:
  const Process_part* part_ = nullptr;
  std::vector<int> caller_;
  std::vector<std::size_t> caller_face_;
  std::vector<char> own_vertex_;
  std::vector<int> vertex_owner_, face_owner_;
};

/// What the report counts of the whole mesh: a process's own rows among `rows` (real vertices), over the processes.
inline std::size_t whole_count(const std::vector<int>& rows, const Part_view& part)
{
  std::size_t own = 0;
  for(int v : rows) own += part.owns_vertex(std::size_t(v)) ? 1 : 0;
  return part.count(own);
}
/// ... of the first `n` rows marked in `marked`
inline std::size_t whole_count(const std::vector<bool>& marked, std::size_t n, const Part_view& part)
{
  std::size_t own = 0;
  for(std::size_t i = 0; i < n; ++i) own += marked[i] && part.owns_vertex(i) ? 1 : 0;
  return part.count(own);
}
/// ... of the first `real_faces` faces
inline std::size_t whole_face_count(std::size_t real_faces, const Part_view& part)
{
  std::size_t own = 0;
  for(std::size_t f = 0; f < real_faces; ++f) own += part.owns_face(f) ? 1 : 0;
  return part.count(own);
}

/// The border loops of the whole mesh: each process's own border vertices give their border edges (by global
/// numbers: a border edge's source is on the border of the whole mesh where its fan is whole), gathered, and the
/// loops among them counted alike on every process.
inline std::size_t whole_boundary_loops(const Ghost_layer& layer, const Part_view& part)
{
  if(part.whole()) return layer.boundary_loops;
  const Triangle_topology& topo = *layer.topology;
  std::vector<double> edges;
  for(int h = 0; h < int(3 * layer.real_faces); ++h)
  {
    const int o = topo.opposite(h), p = topo.source(h);
    if((o >= 0 && std::size_t(topo.face_of(o)) < layer.real_faces) || !part.owns_vertex(std::size_t(p))) continue;
    edges.push_back(double(part.global_vertex(std::size_t(p))));
    edges.push_back(double(part.global_vertex(std::size_t(topo.target(h)))));
  }
  edges = part.gathered(std::move(edges));
  std::unordered_map<std::int64_t, std::int64_t> next;
  for(std::size_t k = 0; k + 1 < edges.size(); k += 2) next[std::int64_t(edges[k])] = std::int64_t(edges[k + 1]);
  std::size_t loops = 0;
  std::unordered_map<std::int64_t, char> seen;
  for(const auto& e : next)
  {
    if(seen.count(e.first)) continue;
    ++loops;
    for(std::int64_t v = e.first; next.count(v) && !seen.count(v); v = next[v]) seen[v] = 1;
  }
  return loops;
}

/// Thrown on the processes whose part passed the input's checks when another's did not: that one reports the error.
struct Input_failed_elsewhere : std::exception
{
  const char* what() const noexcept override { return "another process's part of the mesh failed the input checks"; }
};

/// The input's checks of a mesh in parts, agreed before any exchange: a part that fails them (a check throws) says
/// so as it unwinds, and the other processes then throw Input_failed_elsewhere, so that none waits for another.
class Input_agreement
{
public:
  explicit Input_agreement(const Process_part* part) : part_(part) {}
  Input_agreement(const Input_agreement&) = delete;
  Input_agreement& operator=(const Input_agreement&) = delete;
  ~Input_agreement()
  {
    if(part_ && !agreed_) vote(1);
  }
  void passed()
  {
    agreed_ = true;
    if(part_ && vote(0) > 0) throw Input_failed_elsewhere();
  }

private:
  double vote(double failed) const
  {
    part_->maximum(&failed, 1);
    return failed;
  }
  const Process_part* part_;
  bool agreed_ = false;
};

/// The whole mesh's view, for a measure given none.
inline const Part_view& whole_mesh_view()
{
  static const Part_view whole;
  return whole;
}

} // namespace internal
} // namespace Anisotropic_fairing
} // namespace CGAL

#endif // CGAL_ANISOTROPIC_FAIRING_INTERNAL_MESH_PROCESS_PART_H
