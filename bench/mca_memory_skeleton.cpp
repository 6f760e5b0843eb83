// pair_style mca's memory traffic without its arithmetic: what the data flow of its three passes
// costs per element-step on a plate that fits in the cache and on one that does not.
//
// The same plate as examples/mca-shock's (fcc, 30 cells along x with free ends, W x W cells
// across, periodic), in LAMMPS's order (its atom sort: bins of 0.94 element diameters, x
// fastest), periodic images appended as ghosts, pair mca's half list on that plate (its cutoff
// with the skin, 1.875 d; j after i in that order, each element's partners in ascending index,
// as FixPairState::restore sorts them), a state word per entry, a 21-double row per link (the
// nearest neighbours), and pair mca's per-element arrays with their widths.  Each
// pass reads and writes what pair mca's does (doc/benchmarks/bench_mca.md, "The data flow's own
// cost"), with a few operations per value in place of the physics, and the exchanges with the
// ghosts between the passes done as one rank's copies.  Its numbers are not pair mca's: it
// measures how the cost of a data flow changes with the plate's width, and which data flow
// would change less.
//
// usage: mca_memory_skeleton W STEPS FLOW
//   FLOW  as-is         pair mca's data flow
//         no-rows       every link reads and writes one shared row: the rows' traffic gone
//         volume-own    the volume pass adds to element i only (no writes to partners)
//         volume-gather the volume pass over a full list of the links: each element sums its
//                       own, reading each link's row from either side (ghost pairs from the half
//                       list)
//         force-packed  the force pass reads each partner's data from one 32-double record and
//                       adds its shares to one 8-double record (both filled and emptied by a
//                       loop over the elements, timed with the pass)
//         fused         the plastic and force walks in one loop, the force walk trailing by the
//                       largest j - i of the links; the elements that touch a ghost after it
//         one-record    every per-element array a column of one record per element
// prints the time per element-step of each pass and in all, in us.

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// n rows of w doubles: a block of its own, or w columns of a record shared with other arrays
struct Rows {
  std::vector<double> own;
  int w = 0, stride = 0;
  double *base = nullptr;
  void make(int n, int width)
  {
    w = stride = width;
    own.assign((size_t) n * width + 8, 0.0);
    base = own.data();
  }
  void view(double *b, int s) { base = b, stride = s; }
  double *operator[](int i) const { return base + (size_t) i * stride; }
  void zero(int n) const
  {
    for (int i = 0; i < n; i++) memset((*this)[i], 0, sizeof(double) * w);
  }
};

using Pos = std::array<double, 3>;

struct Plate {
  int nlocal = 0, nall = 0, nrows = 0, maxspan = 0;
  std::vector<Pos> pos;
  std::vector<int> owner, first, list;     // half list: list[first[i] .. first[i+1])
  std::vector<int> slot;                   // each entry's row, -1: an unlinked pair (no row)
  std::vector<int> stop;                   // the passes walk list[first[i] .. stop[i])
  std::vector<int> ffirst, flist, frow;    // full list of owned pairs, with each pair's row
  std::vector<char> touched, deferred;     // fused: sums with ghosts' shares; forces that wait
};

Plate make_plate(int W)
{
  const int L = 30;
  // pair mca's list on the example's plate: the cutoff with the skin, 1.875 d (20.6 entries per
  // element on 3,050); its links, and so its rows, the nearest neighbours only
  // the reach: (1 + tolerance) (R_i + R_j) + skin = 1.02 d + 0.6 d; the first two shells
  const double a = sqrt(2.0), cut = 1.875, link = 1.2, reach = 1.62,
               span[3] = {L * a, W * a, W * a};
  double bin[3];    // LAMMPS's bins: about 0.94 d, a whole number of them across the box
  for (int k = 0; k < 3; k++) bin[k] = span[k] / floor(span[k] / 0.94);
  const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  Plate P;
  for (int i = 0; i < L; i++)
    for (int j = 0; j < W; j++)
      for (int k = 0; k < W; k++)
        for (auto &b : basis)
          P.pos.push_back({(i + b[0] + 0.25) * a, (j + b[1] + 0.25) * a, (k + b[2] + 0.25) * a});
  const int nbx = (int) lround(span[0] / bin[0]) + 1, nby = (int) lround(span[1] / bin[1]) + 5,
            nbz = (int) lround(span[2] / bin[2]) + 5;
  auto cell = [&](const Pos &p, int c[3]) {
    for (int k = 0; k < 3; k++) c[k] = (int) floor(p[k] / bin[k]) + (k ? 2 : 0);
  };
  auto binof = [&](const Pos &p) {
    int c[3];
    cell(p, c);
    return ((long) c[2] * nby + c[1]) * nbx + c[0];
  };
  std::sort(P.pos.begin(), P.pos.end(), [&](const Pos &p, const Pos &q) {
    const long bp = binof(p), bq = binof(q);
    return bp != bq ? bp < bq : p < q;
  });
  P.nlocal = P.pos.size();
  for (int i = 0; i < P.nlocal; i++) P.owner.push_back(i);
  for (int dim = 1; dim <= 2; dim++) {    // images within the cutoff of each periodic face
    const int n = P.pos.size();
    for (int side = 0; side < 2; side++)
      for (int i = 0; i < n; i++) {
        Pos p = P.pos[i];
        if (side == 0 && p[dim] < cut)
          p[dim] += span[dim];
        else if (side == 1 && p[dim] > span[dim] - cut)
          p[dim] -= span[dim];
        else
          continue;
        P.pos.push_back(p);
        P.owner.push_back(P.owner[i]);
      }
  }
  P.nall = P.pos.size();
  std::vector<std::vector<int>> bins((size_t) nbx * nby * nbz);
  for (int i = 0; i < P.nall; i++) bins[binof(P.pos[i])].push_back(i);
  auto after = [&](int i, int j) {
    const long bi = binof(P.pos[i]), bj = binof(P.pos[j]);
    return bj != bi ? bj > bi : P.pos[j] > P.pos[i];
  };
  std::vector<std::vector<std::pair<int, int>>> full(P.nlocal);
  for (int i = 0; i < P.nlocal; i++) {
    P.first.push_back(P.list.size());
    std::vector<int> js;
    int c[3];
    cell(P.pos[i], c);
    for (int dz = -2; dz <= 2; dz++)
      for (int dy = -2; dy <= 2; dy++)
        for (int dx = -2; dx <= 2; dx++) {
          const int x = c[0] + dx, y = c[1] + dy, z = c[2] + dz;
          if (x < 0 || x >= nbx) continue;
          for (int j : bins[((long) z * nby + y) * nbx + x]) {
            double rsq = 0;
            for (int k = 0; k < 3; k++)
              rsq += (P.pos[i][k] - P.pos[j][k]) * (P.pos[i][k] - P.pos[j][k]);
            if (j != i && rsq < cut * cut && after(i, j)) js.push_back(j);
          }
        }
    // FixPairState::restore's order: first, in ascending index, the pairs that may link or touch
    // before the next build (closer than the reach), which the passes walk; then the rest
    auto rsq = [&](int j) {
      double r2 = 0;
      for (int k = 0; k < 3; k++) r2 += (P.pos[i][k] - P.pos[j][k]) * (P.pos[i][k] - P.pos[j][k]);
      return r2;
    };
    auto near = [&](int j) {
      return rsq(j) < reach * reach;
    };
    std::sort(js.begin(), js.end());
    std::stable_partition(js.begin(), js.end(), near);
    P.stop.push_back(P.list.size() + std::count_if(js.begin(), js.end(), near));
    for (int j : js) {
      const bool linked = rsq(j) < link * link;
      P.slot.push_back(linked ? P.nrows++ : -1);
      if (linked && j < P.nlocal) {
        full[i].push_back({j, (int) P.list.size()});
        full[j].push_back({i, (int) P.list.size()});
        P.maxspan = std::max(P.maxspan, j - i);
      }
      P.list.push_back(j);
    }
  }
  P.first.push_back(P.list.size());
  for (int i = 0; i < P.nlocal; i++) {
    std::sort(full[i].begin(), full[i].end());
    P.ffirst.push_back(P.flist.size());
    for (auto &q : full[i]) P.flist.push_back(q.first), P.frow.push_back(q.second);
  }
  P.ffirst.push_back(P.flist.size());
  P.touched.assign(P.nlocal, 0);
  P.deferred.assign(P.nlocal, 0);
  for (int i = 0; i < P.nlocal; i++)
    for (int p = P.first[i]; p < P.first[i + 1]; p++)
      if (P.slot[p] >= 0 && P.list[p] >= P.nlocal) P.touched[i] = P.touched[P.owner[P.list[p]]] = 1;
  for (int i = 0; i < P.nlocal; i++) {
    P.deferred[i] = P.touched[i];
    for (int p = P.first[i]; p < P.first[i + 1]; p++)
      if (P.slot[p] >= 0 && P.list[p] < P.nlocal && P.touched[P.list[p]]) P.deferred[i] = 1;
  }
  return P;
}

}    // namespace

int main(int argc, char **argv)
{
  if (argc != 4) {
    fprintf(stderr, "usage: mca_memory_skeleton W STEPS FLOW (see the source's head)\n");
    return 1;
  }
  const int W = atoi(argv[1]), steps = atoi(argv[2]);
  const std::string flow = argv[3];
  const char *flows[] = {"as-is",        "no-rows", "volume-own", "volume-gather",
                         "force-packed", "fused",   "one-record"};
  if (W < 3 || steps < 1 ||
      std::find(std::begin(flows), std::end(flows), flow) == std::end(flows)) {
    fprintf(stderr,
            "mca_memory_skeleton: W >= 3, STEPS >= 1, FLOW one of as-is no-rows volume-own "
            "volume-gather force-packed fused one-record\n");
    return 1;
  }
  const Plate P = make_plate(W);
  const int nlocal = P.nlocal, nall = P.nall, entries = P.list.size(), nrows = P.nrows;
  const int *list = P.list.data(), *first = P.first.data(), *stop = P.stop.data(),
            *slot = P.slot.data();
  enum { OPEN = 0, LINKED = 1, TOUCHING = 2 };    // each entry's state word, as pair mca's
  double walked = 0;
  for (int i = 0; i < nlocal; i++) walked += stop[i] - first[i];
  std::vector<int> words(entries);
  for (int p = 0; p < entries; p++) words[p] = slot[p] >= 0 ? LINKED : OPEN;

  // pair mca's per-element arrays (LAMMPS's x v f omega torque radius; the components' rows)
  Rows x, v, f, omega, torque, radius, sums, theta, stress, returned, stiff, spring, heat, changes,
      packed, shares;
  Rows *element[] = {&x,     &v,      &f,        &omega, &torque, &radius, &sums,
                     &theta, &stress, &returned, &stiff, &spring, &heat,   &changes};
  const int widths[] = {3, 3, 3, 3, 3, 1, 21, 1, 9, 2, 1, 2, 1, 4};
  std::vector<double> record;
  int width = 0;
  for (int k = 0; k < 14; k++) element[k]->make(nall, widths[k]), width += widths[k];
  if (flow == "one-record") {
    record.assign((size_t) nall * width + 8, 0.0);
    for (int k = 0, off = 0; k < 14; off += widths[k++])
      element[k]->view(record.data() + off, width);
  }
  packed.make(nall, 32);
  shares.make(nall, 8);
  for (int i = 0; i < nall; i++) {
    for (int k = 0; k < 3; k++) x[i][k] = P.pos[i][k], v[i][k] = 1e-3 * ((i * 7 + k) % 5);
    radius[i][0] = 0.5, stiff[i][0] = 1.0, spring[i][0] = 0.1;
  }
  Rows rows;
  rows.make(nrows, 21);
  if (flow == "no-rows") rows.stride = 0;
  for (int p = 0; p < nrows; p++) rows[p][0] = 1.0, rows[p][1] = 0.5;

  // the volume pass's share of one pair, and its writes to the pair's row
  auto volume_share = [&](int i, int j, double *r, double *ws, double &e) {
    const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
    const double w = r[1] * r[8] / r[0];
    e = d[0] * r[5] + d[1] * r[6] + d[2] * r[7] + r[9];
    for (int k = 0; k < 21; k++) ws[k] = w * d[k % 3] * d[(k + 1) % 3];
  };
  auto volume_scatter = [&](int i, int p, bool partner) {
    const int j = list[p];
    double *r = rows[slot[p]], ws[21], e;
    volume_share(i, j, r, ws, e);
    for (int k = 0; k < 21; k++) sums[i][k] += ws[k];
    theta[i][0] += e * stiff[i][0];
    if (partner) {
      for (int k = 0; k < 21; k++) sums[j][k] += ws[k];
      theta[j][0] += e * stiff[j][0];
    }
    r[15] = 1e-9 * e, r[14] += r[15];
  };
  auto plastic_element = [&](int i) {
    for (int p = first[i]; p < stop[i]; p++) {
      if (words[p] != LINKED) continue;
      const int j = list[p];
      double *r = rows[slot[p]];
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double turn = omega[i][0] + omega[j][1];
      for (int k = 2; k < 5; k++) r[k] += 1e-9 * (turn + r[k + 9]);
      for (int k = 11; k < 14; k++) r[k] += 1e-9 * d[0];
      r[10] = stiff[i][0] * stiff[j][0] / (stiff[i][0] + stiff[j][0]) * (d[0] + r[15] + r[8]);
      r[16] = 1e-9 * r[10] * r[10];
      const double sym[9] = {d[0] * d[0], d[1] * d[1], d[2] * d[2], d[0] * d[1], d[0] * d[2],
                             d[1] * d[2], 1.0,         r[10],       1.0};
      for (int k = 0; k < 9; k++) stress[i][k] += r[10] * sym[k], stress[j][k] += r[10] * sym[k];
    }
  };
  auto return_element = [&](int i) {
    returned[i][0] = 1.0 / (1.0 + 1e-9 * stress[i][0]);
    returned[i][1] = stress[i][7] / (stress[i][8] + 1.0);
  };
  // the force pass's work on one pair from the partners' values; 'to' takes the shares
  auto pair_force = [&](double *r, const double *d, double ri, double rj, double pn, double phi,
                        double hg, double oi, double oj, double *si, double *sj) {
    const double sig = phi * r[10] + 1e-3 * pn, pull = r[14] * hg;
    r[8] = std::max(r[8], 1e-9 * fabs(sig));
    r[17] += pull * r[15], r[18] = pull, r[19] = r[2] + r[3] + r[4];
    for (int k = 0; k < 3; k++) r[5 + k] = d[k];
    const double fk[3] = {sig * d[0] * r[1] * (ri + rj), sig * d[1] * r[1], sig * d[2] * r[1]};
    for (int k = 0; k < 3; k++) si[k] += fk[k], sj[k] -= fk[k];
    si[3] += 1e-9 * (oi - oj), si[4] += fk[1] * ri, si[5] += fk[2] * ri;
    sj[3] -= 1e-9 * (oi - oj), sj[4] += fk[1] * rj, sj[5] += fk[2] * rj;
    si[6] += 1e-9 * r[16], sj[6] += 1e-9 * r[16];
    si[7] += 1e-9 * r[15], sj[7] += 1e-9 * r[15];
  };
  // an unlinked pair: apart, or touching (pair mca's contact law would follow)
  auto contact = [&](int p, const double *d, double ri, double rj) {
    words[p] = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < (ri + rj) * (ri + rj) ? TOUCHING : OPEN;
  };
  auto force_element = [&](int i) {
    for (int p = first[i]; p < stop[i]; p++) {
      const int j = list[p];
      const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      if (words[p] != LINKED) {
        contact(p, d, radius[i][0], radius[j][0]);
        continue;
      }
      double pn = 0;
      for (int k = 0; k < 15; k++) pn += sums[i][k] + sums[j][k];
      double si[8] = {0}, sj[8] = {0};
      pair_force(rows[slot[p]], d, radius[i][0], radius[j][0], pn,
                 std::min(returned[i][0], returned[j][0]),
                 (spring[i][0] + spring[j][0]) / (stiff[i][0] + stiff[j][0]), omega[i][2],
                 omega[j][2], si, sj);
      for (int k = 0; k < 3; k++) f[i][k] += si[k], f[j][k] += sj[k];
      for (int k = 0; k < 3; k++) torque[i][k] += si[3 + k], torque[j][k] += sj[3 + k];
      heat[i][0] += si[6], heat[j][0] += sj[6], changes[i][3] += si[7], changes[j][3] += sj[7];
    }
  };
  auto force_packed = [&] {
    for (int i = 0; i < nall; i++) {
      double *q = packed[i];
      for (int k = 0; k < 3; k++) q[k] = x[i][k];
      q[3] = radius[i][0], q[4] = stiff[i][0], q[5] = spring[i][0], q[6] = returned[i][0],
      q[7] = omega[i][2];
      for (int k = 0; k < 15; k++) q[8 + k] = sums[i][k];
    }
    shares.zero(nall);
    for (int i = 0; i < nlocal; i++) {
      const double *qi = packed[i];
      for (int p = first[i]; p < stop[i]; p++) {
        const double *qj = packed[list[p]];
        const double d[3] = {qj[0] - qi[0], qj[1] - qi[1], qj[2] - qi[2]};
        if (words[p] != LINKED) {
          contact(p, d, qi[3], qj[3]);
          continue;
        }
        double pn = 0;
        for (int k = 0; k < 15; k++) pn += qi[8 + k] + qj[8 + k];
        pair_force(rows[slot[p]], d, qi[3], qj[3], pn, std::min(qi[6], qj[6]),
                   (qi[5] + qj[5]) / (qi[4] + qj[4]), qi[7], qj[7], shares[i], shares[list[p]]);
      }
    }
    for (int i = 0; i < nall; i++) {
      const double *q = shares[i];
      for (int k = 0; k < 3; k++) f[i][k] += q[k], torque[i][k] += q[3 + k];
      heat[i][0] += q[6], changes[i][3] += q[7];
    }
  };
  auto to_owners = [&](const Rows &a, int n) {
    for (int g = nlocal; g < nall; g++)
      for (int k = 0; k < n; k++) a[P.owner[g]][k] += a[g][k];
  };
  auto to_ghosts = [&](const Rows &a, int n) {
    for (int g = nlocal; g < nall; g++) memcpy(a[g], a[P.owner[g]], sizeof(double) * n);
  };

  double t[4] = {0, 0, 0, 0}, forces = 0;
  for (int s = 0; s < steps; s++) {
    double t0 = now();
    sums.zero(nall), theta.zero(nall);
    if (flow == "volume-gather") {
      for (int i = 0; i < nlocal; i++) {
        double si[21] = {0}, th = 0, ws[21], e;
        for (int q = P.ffirst[i]; q < P.ffirst[i + 1]; q++) {
          const int j = P.flist[q], p = P.frow[q];
          const bool mine = list[p] == j && p >= first[i] && p < stop[i];    // the row is i's
          double *r = rows[slot[p]];
          volume_share(mine ? i : j, mine ? j : i, r, ws, e);    // in the row's own orientation
          for (int k = 0; k < 21; k++) si[k] += ws[k];
          th += e * stiff[i][0];
          if (mine) r[15] = 1e-9 * e, r[14] += r[15];    // the row's own side writes it
        }
        for (int k = 0; k < 21; k++) sums[i][k] += si[k];
        theta[i][0] += th;
      }
      for (int i = 0; i < nlocal; i++)
        for (int p = first[i]; p < stop[i]; p++)
          if (words[p] == LINKED && list[p] >= nlocal) volume_scatter(i, p, true);
    } else {
      const bool partner = flow != "volume-own";
      for (int i = 0; i < nlocal; i++)
        for (int p = first[i]; p < stop[i]; p++)
          if (words[p] == LINKED) volume_scatter(i, p, partner);
    }
    double t1 = now();
    to_owners(sums, 21), to_owners(theta, 1);
    for (int i = 0; i < nlocal; i++) {    // the elements' update: pressures in the first 15
      const double trace = sums[i][0] + sums[i][1] + sums[i][2];
      for (int k = 0; k < 15; k++) sums[i][k] = 1e-3 * trace + 1e-6 * sums[i][k + 6];
    }
    to_ghosts(sums, 15), to_ghosts(theta, 1);
    stress.zero(nall), heat.zero(nall), changes.zero(nall);
    double t2 = now();
    if (flow == "fused") {
      for (int c = 0; c < nlocal + P.maxspan; c++) {
        if (c < nlocal) {
          plastic_element(c);
          if (!P.touched[c]) return_element(c);
        }
        if (c >= P.maxspan && !P.deferred[c - P.maxspan]) force_element(c - P.maxspan);
      }
    } else
      for (int i = 0; i < nlocal; i++) plastic_element(i);
    to_owners(stress, 9);
    for (int i = 0; i < nlocal; i++)
      if (flow != "fused" || P.touched[i]) return_element(i);
    to_ghosts(returned, 2);
    double t3 = now();
    if (flow == "force-packed")
      force_packed();
    else
      for (int i = 0; i < nlocal; i++)
        if (flow != "fused" || P.deferred[i]) force_element(i);
    to_owners(f, 3), to_owners(torque, 3), to_owners(heat, 1), to_owners(changes, 4);
    for (int i = 0; i < nlocal; i++)    // the integrator's share, so that the forces are used
      for (int k = 0; k < 3; k++) v[i][k] += 1e-12 * f[i][k], forces += fabs(f[i][k]);
    f.zero(nall), torque.zero(nall);
    double t4 = now();
    t[0] += t1 - t0, t[1] += t2 - t1, t[2] += t3 - t2, t[3] += t4 - t3;
  }
  double volumes = 0, heats = 0;    // the sums each flow should keep (up to their order)
  for (int i = 0; i < nlocal; i++) volumes += theta[i][0], heats += heat[i][0];
  const double per = 1e6 / ((double) nlocal * steps);
  printf(
      "%s W %d elements %d ghosts %d entries/element %.2f walked/element %.2f rows/element %.2f  "
      "us per element-step: "
      "volume %.4f update %.4f plastic %.4f force %.4f all %.4f  sums: volume %.15g heat %.15g "
      "force %.15g\n",
      flow.c_str(), W, nlocal, nall - nlocal, (double) entries / nlocal, walked / nlocal,
      (double) nrows / nlocal, t[0] * per, t[1] * per, t[2] * per, t[3] * per,
      (t[0] + t[1] + t[2] + t[3]) * per, volumes, heats, forces);
  return 0;
}
