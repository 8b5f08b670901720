// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The exchanges a part of the mesh is made and kept by (Mesh_part.h): contiguous blocks of numbers (what each
// process reads of a file: Mesh_blocks, Ply_blocks.h), and records sent to chosen processes in one MPI_Alltoallv.

#ifndef AF_DISTRIBUTED_PART_EXCHANGE_H
#define AF_DISTRIBUTED_PART_EXCHANGE_H

#include <mpi.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace af_distributed {

inline int rank_of(MPI_Comm comm)
{
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

/// The first of the `total` numbers the block of process `p` of `size` holds (block p: [first(p), first(p + 1))).
inline std::int64_t block_first(std::int64_t total, int p, int size) { return total * p / size; }

/// The process whose block holds number `id` of `total`.
inline int block_of(std::int64_t id, std::int64_t total, int size)
{
  int p = int(((id + 1) * size - 1) / total);   // the least p with first(p + 1) > id, up to rounding
  while(p > 0 && block_first(total, p, size) > id) --p;
  while(p + 1 < size && block_first(total, p + 1, size) <= id) ++p;
  return p;
}

/// What a process read: the whole mesh's sizes and its blocks of them (block_first() says which).
struct Mesh_blocks
{
  std::int64_t vertices = 0, faces = 0;
  std::vector<double> points;                           // 3 per vertex of this process's block
  std::vector<std::array<std::int64_t, 3>> triangles;   // this process's block of faces, by global vertex numbers
};

/// `out[p]` sent to process p; what the others sent here, by process (`from`, if given: each record's sender).
template <typename T>
std::vector<T> exchange(MPI_Comm comm, const std::vector<std::vector<T>>& out, std::vector<int>* from = nullptr)
{
  static_assert(std::is_trivially_copyable<T>::value, "records cross as bytes");
  const int size = int(out.size());
  const std::size_t processes = out.size();
  std::vector<int> send_count(processes), receive_count(processes), send_at(processes), receive_at(processes);
  std::vector<T> send;
  for(int p = 0; p < size; ++p)
  {
    send_at[std::size_t(p)] = int(send.size() * sizeof(T));
    send_count[std::size_t(p)] = int(out[std::size_t(p)].size() * sizeof(T));
    send.insert(send.end(), out[std::size_t(p)].begin(), out[std::size_t(p)].end());
  }
  MPI_Alltoall(send_count.data(), 1, MPI_INT, receive_count.data(), 1, MPI_INT, comm);
  long long total = 0;
  for(int p = 0; p < size; ++p)
  {
    receive_at[std::size_t(p)] = int(total);
    total += receive_count[std::size_t(p)];
  }
  if(total > 2147483647LL) throw std::runtime_error("a part's exchange exceeds 2 GB: run on more processes");
  std::vector<T> in(std::size_t(total) / sizeof(T));
  MPI_Alltoallv(send.data(), send_count.data(), send_at.data(), MPI_BYTE, in.data(), receive_count.data(),
                receive_at.data(), MPI_BYTE, comm);
  if(from)
  {
    from->clear();
    for(int p = 0; p < size; ++p) from->insert(from->end(), std::size_t(receive_count[std::size_t(p)]) / sizeof(T), p);
  }
  return in;
}

/// `out` (send_count[p] records of `columns` doubles for each process p, in order) sent; receive_count[p] records
/// from each process p back, in order.
inline std::vector<double> exchange_counted(MPI_Comm comm, const std::vector<double>& out,
                                            const std::vector<int>& send_count, const std::vector<int>& receive_count,
                                            int columns)
{
  const std::size_t size = send_count.size();
  std::vector<int> sc(size), sa(size), rc(size), ra(size);
  int s = 0, r = 0;
  for(std::size_t p = 0; p < size; ++p)
  {
    sc[p] = send_count[p] * columns;
    rc[p] = receive_count[p] * columns;
    sa[p] = s;
    ra[p] = r;
    s += sc[p];
    r += rc[p];
  }
  std::vector<double> in(static_cast<std::size_t>(r));
  MPI_Alltoallv(out.data(), sc.data(), sa.data(), MPI_DOUBLE, in.data(), rc.data(), ra.data(), MPI_DOUBLE, comm);
  return in;
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_PART_EXCHANGE_H
