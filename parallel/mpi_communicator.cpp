#include "mpi_communicator.hpp"

#include <algorithm>
#include <climits>
#include <stdexcept>

namespace granshock {

namespace {

void require(int status, const char* what) {
  if (status != MPI_SUCCESS) throw std::runtime_error(std::string(what) + " failed");
}

}  // namespace

MpiCommunicator::MpiCommunicator(MPI_Comm comm) : comm_(comm) {
  require(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  require(MPI_Comm_size(comm_, &size_), "MPI_Comm_size");
}

double MpiCommunicator::max(double local) const {
  double out = 0;
  require(MPI_Allreduce(&local, &out, 1, MPI_DOUBLE, MPI_MAX, comm_), "MPI_Allreduce (max)");
  return out;
}

double MpiCommunicator::sum(double local) const {
  double out = 0;
  require(MPI_Allreduce(&local, &out, 1, MPI_DOUBLE, MPI_SUM, comm_), "MPI_Allreduce (sum)");
  return out;
}

long MpiCommunicator::sum(long local) const {
  long out = 0;
  require(MPI_Allreduce(&local, &out, 1, MPI_LONG, MPI_SUM, comm_), "MPI_Allreduce (sum)");
  return out;
}

bool MpiCommunicator::any(bool local) const {
  int flag = local ? 1 : 0, out = 0;
  require(MPI_Allreduce(&flag, &out, 1, MPI_INT, MPI_LOR, comm_), "MPI_Allreduce (any)");
  return out != 0;
}

void MpiCommunicator::sum_in_place(std::vector<double>& values) const {
  // In pieces of at most INT_MAX elements: MPI counts are int.
  for (std::size_t done = 0; done < values.size();) {
    const int count = int(std::min<std::size_t>(values.size() - done, INT_MAX));
    require(MPI_Allreduce(MPI_IN_PLACE, values.data() + done, count, MPI_DOUBLE, MPI_SUM, comm_),
            "MPI_Allreduce (sum in place)");
    done += std::size_t(count);
  }
}

std::vector<char> MpiCommunicator::send_receive(const std::vector<char>& bytes, int dest,
                                                int source) const {
  const int to = dest == kNone ? MPI_PROC_NULL : dest;
  const int from = source == kNone ? MPI_PROC_NULL : source;
  if (bytes.size() > std::size_t(INT_MAX))
    throw std::runtime_error("a halo message of more than 2 GiB");
  // The size first, then the bytes: the receiver allocates what it is sent.
  int count = int(bytes.size()), incoming = 0;
  require(MPI_Sendrecv(&count, 1, MPI_INT, to, 1, &incoming, 1, MPI_INT, from, 1, comm_,
                       MPI_STATUS_IGNORE),
          "MPI_Sendrecv (size)");
  std::vector<char> received(static_cast<std::size_t>(incoming));
  require(MPI_Sendrecv(bytes.data(), count, MPI_BYTE, to, 2, received.data(), incoming, MPI_BYTE,
                       from, 2, comm_, MPI_STATUS_IGNORE),
          "MPI_Sendrecv (bytes)");
  return received;
}

std::vector<char> MpiCommunicator::gather(const std::vector<char>& bytes, int root) const {
  return gather_to(bytes, root, false);
}

std::vector<char> MpiCommunicator::all_gather(const std::vector<char>& bytes) const {
  return gather_to(bytes, 0, true);
}

// The sizes first (to every rank, or to the root), then the bytes at their offsets.
std::vector<char> MpiCommunicator::gather_to(const std::vector<char>& bytes, int root,
                                             bool everywhere) const {
  if (bytes.size() > std::size_t(INT_MAX))
    throw std::runtime_error("a gathered message of more than 2 GiB");
  const int count = int(bytes.size());
  std::vector<int> counts(std::size_t(size_), 0), offsets(std::size_t(size_), 0);
  if (everywhere) {
    require(MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm_),
            "MPI_Allgather (sizes)");
  } else {
    require(MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, root, comm_),
            "MPI_Gather (sizes)");
  }
  long total = 0;
  for (int r = 0; r < size_; ++r) {
    offsets[std::size_t(r)] = int(total);
    total += counts[std::size_t(r)];
  }
  if (total > long(INT_MAX)) throw std::runtime_error("a gathered message of more than 2 GiB");
  const bool receives = everywhere || rank_ == root;
  std::vector<char> out(receives ? std::size_t(total) : 0);
  if (everywhere) {
    require(MPI_Allgatherv(bytes.data(), count, MPI_BYTE, out.data(), counts.data(), offsets.data(),
                           MPI_BYTE, comm_),
            "MPI_Allgatherv");
  } else {
    require(MPI_Gatherv(bytes.data(), count, MPI_BYTE, out.data(), counts.data(), offsets.data(),
                        MPI_BYTE, root, comm_),
            "MPI_Gatherv");
  }
  return out;
}

}  // namespace granshock
