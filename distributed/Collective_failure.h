// Copyright (c) 2026 Anisotropic_fairing developers.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One process's failure is the whole run's. Every process calls agree() at the same points of the run
// with what went wrong on its side (empty: nothing); if any process failed, all of them throw the
// message of the lowest failing rank, so that every process takes the same decision and the run ends
// before anything is written.

#ifndef AF_DISTRIBUTED_COLLECTIVE_FAILURE_H
#define AF_DISTRIBUTED_COLLECTIVE_FAILURE_H

#include <mpi.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace af_distributed {

/// The run failed on some process (what(): that process's message, prefixed by its rank when several run).
struct Collective_failure : std::runtime_error
{
  std::string status;
  Collective_failure(const std::string& s, const std::string& message) : std::runtime_error(message), status(s) {}
};

/// Throws Collective_failure on every process of `comm` when `message` is not empty on at least one;
/// `status`: the report's word for the failure (of the lowest failing rank).
inline void agree(MPI_Comm comm, const std::string& message, const std::string& status = "error")
{
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int mine = message.empty() ? size : rank;
  int first = size, failed = 0, one = message.empty() ? 0 : 1;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if(first == size) return;
  MPI_Allreduce(&one, &failed, 1, MPI_INT, MPI_SUM, comm);
  const std::string text = status + '\n' + message;
  int length = rank == first ? int(text.size()) : 0;
  MPI_Bcast(&length, 1, MPI_INT, first, comm);
  std::vector<char> buffer(text.begin(), text.end());
  buffer.resize(std::size_t(length));
  MPI_Bcast(buffer.data(), length, MPI_CHAR, first, comm);
  const std::string received(buffer.begin(), buffer.end());
  const std::size_t cut = received.find('\n');
  // the process is named when not every process failed (a failure of its part)
  const std::string where = failed < size ? "process " + std::to_string(first) + ": " : std::string();
  throw Collective_failure(received.substr(0, cut), where + received.substr(cut + 1));
}

/// Runs f(); an exception it throws on one process becomes every process's Collective_failure.
template <typename F>
void agree_on(MPI_Comm comm, const F& f, const std::string& status = "error")
{
  std::string message;
  try { f(); }
  catch(const Collective_failure&) { throw; }
  catch(const std::exception& e) { message = e.what(); if(message.empty()) message = "unknown error"; }
  agree(comm, message, status);
}

} // namespace af_distributed

#endif // AF_DISTRIBUTED_COLLECTIVE_FAILURE_H
