#include "parallel/mpi_communicator.hpp"

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

// Tags tell the direction apart when the lower and upper neighbour are the same rank
// (two slabs on a periodic axis): what travels down is received from above.
NeighbourBytes MpiCommunicator::exchange_with_neighbours(const std::vector<char>& to_lower,
                                                         int lower,
                                                         const std::vector<char>& to_upper,
                                                         int upper, ExpectedBytes expected) const {
  enum Tag { size_down = 11, size_up = 12, bytes_down = 21, bytes_up = 22 };
  const int below = lower == kNone ? MPI_PROC_NULL : lower;
  const int above = upper == kNone ? MPI_PROC_NULL : upper;
  for (const std::vector<char>* out : {&to_lower, &to_upper})
    if (out->size() > std::size_t(INT_MAX))
      throw std::runtime_error("a halo message of more than 2 GiB");
  long from_lower = lower == kNone ? 0 : expected.from_lower;
  long from_upper = upper == kNone ? 0 : expected.from_upper;
  MPI_Request requests[4];
  if (from_lower < 0 || from_upper < 0) {
    long down = long(to_lower.size()), up = long(to_upper.size());
    from_lower = from_upper = 0;  // stays 0 from MPI_PROC_NULL
    MPI_Irecv(&from_lower, 1, MPI_LONG, below, size_up, comm_, &requests[0]);
    MPI_Irecv(&from_upper, 1, MPI_LONG, above, size_down, comm_, &requests[1]);
    MPI_Isend(&down, 1, MPI_LONG, below, size_down, comm_, &requests[2]);
    MPI_Isend(&up, 1, MPI_LONG, above, size_up, comm_, &requests[3]);
    require(MPI_Waitall(4, requests, MPI_STATUSES_IGNORE), "MPI_Waitall (sizes)");
  }
  NeighbourBytes in;
  in.lower.resize(std::size_t(from_lower));
  in.upper.resize(std::size_t(from_upper));
  MPI_Irecv(in.lower.data(), int(from_lower), MPI_BYTE, below, bytes_up, comm_, &requests[0]);
  MPI_Irecv(in.upper.data(), int(from_upper), MPI_BYTE, above, bytes_down, comm_, &requests[1]);
  MPI_Isend(to_lower.data(), int(to_lower.size()), MPI_BYTE, below, bytes_down, comm_,
            &requests[2]);
  MPI_Isend(to_upper.data(), int(to_upper.size()), MPI_BYTE, above, bytes_up, comm_, &requests[3]);
  require(MPI_Waitall(4, requests, MPI_STATUSES_IGNORE), "MPI_Waitall (bytes)");
  return in;
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
