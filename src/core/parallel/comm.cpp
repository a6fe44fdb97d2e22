#include "core/parallel/comm.h"

namespace mpmice::core {

Comm::Comm(MPI_Comm c) : comm_(c) {
  MPI_Comm_rank(c, &rank_);
  MPI_Comm_size(c, &size_);
}

double Comm::sum(double v) const {
  double r = 0;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_SUM, comm_);
  return r;
}
double Comm::max(double v) const {
  double r = 0;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MAX, comm_);
  return r;
}
double Comm::min(double v) const {
  double r = 0;
  MPI_Allreduce(&v, &r, 1, MPI_DOUBLE, MPI_MIN, comm_);
  return r;
}
long long Comm::sum(long long v) const {
  long long r = 0;
  MPI_Allreduce(&v, &r, 1, MPI_LONG_LONG, MPI_SUM, comm_);
  return r;
}
int Comm::max(int v) const {
  int r = 0;
  MPI_Allreduce(&v, &r, 1, MPI_INT, MPI_MAX, comm_);
  return r;
}
void Comm::sumInPlace(std::vector<double>& v) const {
  MPI_Allreduce(MPI_IN_PLACE, v.data(), static_cast<int>(v.size()), MPI_DOUBLE, MPI_SUM, comm_);
}
void Comm::barrier() const { MPI_Barrier(comm_); }

}  // namespace mpmice::core
