/* ----------------------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: compute dust's sums per fragment
   (fragment_sums.h).
------------------------------------------------------------------------- */

#include "fragment_sums.h"

#include "mpi_collectives.h"

using namespace LAMMPS_NS;
using namespace ClusterDyn;

static constexpr int RECORD = 1 + FragmentSums::NSUMS;    // fragment ID, sums

void FragmentSums::add(tagint id, double m, const double *xu, const double *v)
{
  Sums &sums = mine[id];
  sums[SIZE] += 1.0;
  sums[MASS] += m;
  for (int d = 0; d < 3; d++) {
    sums[MX + d] += m * xu[d];
    sums[MV + d] += m * v[d];
  }
}

void FragmentSums::combine()
{
  int nprocs;
  MPI_Comm_size(world, &nprocs);
  outbox.assign(nprocs, {});
  for (const auto &kv : mine) {
    auto &box = outbox[kv.first % nprocs];
    box.push_back((double) kv.first);
    box.insert(box.end(), kv.second.begin(), kv.second.end());
  }
  inbox = alltoallv(outbox, incounts, world);
  for (size_t k = 0; k < inbox.size(); k += RECORD) {
    Sums &sums = owned_[(tagint) inbox[k]];
    for (int c = 0; c < NSUMS; c++) sums[c] += inbox[k + 1 + c];
  }

  // the body: the largest fragment, the smallest ID among equals
  double mybody[2] = {0.0, 0.0};    // (size, -ID) of my largest, then everybody's
  for (const auto &kv : owned_)
    if (kv.second[SIZE] > mybody[0]) {
      mybody[0] = kv.second[SIZE];
      mybody[1] = -(double) kv.first;
    }
  double body[2];
  MPI_Allreduce(&mybody[0], &body[0], 1, MPI_DOUBLE, MPI_MAX, world);
  if (mybody[0] < body[0]) mybody[1] = -(double) MAXTAGINT;
  MPI_Allreduce(&mybody[1], &body[1], 1, MPI_DOUBLE, MPI_MAX, world);
  body_size_ = body[0];
  body_id = (tagint) -body[1];
}

// (size, dust flag) for each ID each processor sent, in its order; they come back grouped by
// owner, in my order
std::unordered_map<tagint, FragmentSums::Answer> FragmentSums::answers() const
{
  const int nprocs = outbox.size();
  std::vector<std::vector<double>> replies(nprocs);
  for (int p = 0, k = 0; p < nprocs; p++)
    for (int n = 0; n < incounts[p] / RECORD; n++, k += RECORD) {
      const tagint id = (tagint) inbox[k];
      const double size = owned_.at(id)[SIZE];
      replies[p].push_back(size);
      replies[p].push_back(is_dust(id, size) ? 1.0 : 0.0);
    }
  std::vector<int> replycounts;
  const std::vector<double> answers = alltoallv(replies, replycounts, world);
  std::unordered_map<tagint, Answer> mysizes;
  for (int p = 0, a = 0; p < nprocs; p++)
    for (size_t k = 0; k < outbox[p].size(); k += RECORD, a += 2)
      mysizes[(tagint) outbox[p][k]] = {answers[a], answers[a + 1]};
  return mysizes;
}
