#include "core/parallel/comm.h"

namespace mpmice::core {

Comm::Comm(MPI_Comm c) : comm_(c) {
  MPI_Comm_rank(c, &rank_);
  MPI_Comm_size(c, &size_);
}

namespace {
template <class T>
T allReduce(T v, MPI_Datatype type, MPI_Op op, MPI_Comm comm) {
  T r{};
  MPI_Allreduce(&v, &r, 1, type, op, comm);
  return r;
}
}  // namespace

double Comm::sum(double v) const { return allReduce(v, MPI_DOUBLE, MPI_SUM, comm_); }
double Comm::max(double v) const { return allReduce(v, MPI_DOUBLE, MPI_MAX, comm_); }
double Comm::min(double v) const { return allReduce(v, MPI_DOUBLE, MPI_MIN, comm_); }
long long Comm::sum(long long v) const { return allReduce(v, MPI_LONG_LONG, MPI_SUM, comm_); }
int Comm::max(int v) const { return allReduce(v, MPI_INT, MPI_MAX, comm_); }
void Comm::sumInPlace(std::vector<double>& v) const {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm_);
}
void Comm::barrier() const { MPI_Barrier(comm_); }

std::string Comm::firstMessage(const std::string& mine) const {
  const int owner = size_ - max(mine.empty() ? 0 : size_ - rank_);  // size_: nobody has one
  if (owner == size_) return "";
  int n = rank_ == owner ? static_cast<int>(mine.size()) : 0;
  MPI_Bcast(&n, 1, MPI_INT, owner, comm_);
  std::string s = rank_ == owner ? mine : std::string(static_cast<std::size_t>(n), ' ');
  MPI_Bcast(s.data(), n, MPI_CHAR, owner, comm_);
  return s;
}

}  // namespace mpmice::core
