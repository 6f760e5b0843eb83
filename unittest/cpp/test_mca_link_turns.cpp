// McaLinkTurns (mca_link_turns.h): the plastic pass's turn and slide of a batch of links side by
// side are the scalar functions link by link (McaPairFrame::turn, McaContact::slide,
// McaLinkedPair::rotate), over several batches and with a part-filled one; a batch with a turn
// beyond the series takes the scalar functions; without motion nothing turns; a rigid rotation
// of every link turns its stored stress and makes no work (closed forms).
#include "mca_link_turns.h"

#include "gtest/gtest.h"

#include <cmath>
#include <random>
#include <vector>

using namespace LAMMPS_NS::ClusterDyn;
using C = McaContact;

namespace {

struct Link {
  double xi[3], xj[3], oi[3], oj[3], ri, rj, a;
  std::vector<double> v = std::vector<double>(C::NVALUES, 0.0);
};

// links of unit-order separations, stored vectors and spins of `turn` radians per step or less
std::vector<Link> links(int count, double turn, unsigned seed)
{
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Link> out(count);
  for (auto &l : out) {
    for (int k = 0; k < 3; k++) {
      l.xi[k] = u(gen);
      l.xj[k] = l.xi[k] + (k == 0 ? 1.0 : 0.0) + 0.2 * u(gen);
      l.oi[k] = turn * u(gen) / std::sqrt(3.0);
      l.oj[k] = turn * u(gen) / std::sqrt(3.0);
      l.v[C::TAU + k] = u(gen);
      l.v[C::DPREV + k] = l.xj[k] - l.xi[k] + 0.01 * u(gen);
      l.v[C::ROT + k] = 0.1 * u(gen);
    }
    l.ri = 0.5 + 0.1 * u(gen);
    l.rj = 0.5 + 0.1 * u(gen);
    l.a = 2.0 + u(gen);
    for (const int k : {C::REF, C::AREA, C::KAPPA, C::EPL, C::SIG, C::HG, C::DR, C::EHG, C::FHG})
      l.v[k] = u(gen);
    l.v[C::ET] = 0.5 + u(gen);
  }
  return out;
}

McaPairFrame frame(Link &l)
{
  double *x[2] = {l.xi, l.xj};
  McaPairFrame p(x, 0, 1);
  p.orient(l.ri, l.rj);
  return p;
}

// the scalar functions, as the plastic pass took them link by link
void scalar(Link &l, double dt, bool moving)
{
  const McaPairFrame p = frame(l);
  const C::Turn turn = moving ? p.turn(l.oi, l.oj, dt) : C::Turn();
  double dut[3];
  double *v = l.v.data();
  C::slide(v + C::TAU, v + C::DPREV, p.d, p.n, moving ? &turn : nullptr, l.a, dut, v + C::ET);
  v[C::DTAU] = moving ? C::dot(v + C::TAU, dut) : 0.0;
  if (moving) McaLinkedPair::rotate(v, turn, l.oi, l.oj, dt);
}

// the batch, flushed when full and at the end
void batched(std::vector<Link> &all, double dt, bool moving)
{
  McaLinkTurns turns;
  for (auto &l : all)
    if (turns.add(0, 1, l.v.data(), frame(l), l.a, l.oi, l.oj, dt, moving)) {
      turns.advance();
      turns.clear();
    }
  turns.advance();
}

void expect_same(const std::vector<Link> &a, const std::vector<Link> &b)
{
  for (std::size_t l = 0; l < a.size(); l++)
    for (int k = 0; k < C::NVALUES; k++)
      EXPECT_NEAR(a[l].v[k], b[l].v[k], 1e-15 * (1.0 + std::fabs(b[l].v[k])))
          << "link " << l << " value " << k;
}

}    // namespace

TEST(McaLinkTurns, ABatchIsTheScalarFunctionsLinkByLink)
{
  const double dt = 0.1;
  for (const int count : {1, 16, 37}) {    // part-filled, one full batch, two and a part
    auto side = links(count, 1e-3 / dt, 7 + count), one = side;
    batched(side, dt, true);
    for (auto &l : one) scalar(l, dt, true);
    expect_same(side, one);
    for (std::size_t l = 0; l < side.size(); l++)    // and they did change
      EXPECT_NE(side[l].v[C::ROT], links(count, 1e-3 / dt, 7 + count)[l].v[C::ROT]);
  }
}

TEST(McaLinkTurns, ATurnBeyondTheSeriesTakesTheScalarFunctions)
{
  const double dt = 1.0;
  auto side = links(5, 1e-3, 11);
  for (int k = 0; k < 3; k++) side[3].oi[k] = side[3].oj[k] = 0.05;    // a = 0.087 rad a step
  auto one = side;
  batched(side, dt, true);
  for (auto &l : one) scalar(l, dt, true);
  expect_same(side, one);
}

TEST(McaLinkTurns, WithoutMotionNothingTurnsAndNothingRotates)
{
  auto side = links(20, 1.0, 13), before = side, one = side;
  batched(side, 0.1, false);
  for (auto &l : one) scalar(l, 0.1, false);
  expect_same(side, one);
  for (std::size_t l = 0; l < side.size(); l++) {
    EXPECT_EQ(side[l].v[C::DTAU], 0.0);
    for (int k = 0; k < 3; k++) EXPECT_EQ(side[l].v[C::ROT + k], before[l].v[C::ROT + k]);
  }
}

// every link's pair and both its elements turned rigidly by 0.005 rad about z (in the series):
// its tangential stress turns with it at its magnitude, no slide, no work, its relative rotation
// turns too
TEST(McaLinkTurns, ARigidRotationTurnsTheStressAndDoesNoWork)
{
  const double angle = 0.005, dt = 0.5, c = std::cos(angle), s = std::sin(angle);
  auto side = links(21, 1.0, 17);
  for (auto &l : side) {
    double d[3];
    for (int k = 0; k < 3; k++) d[k] = l.xj[k] - l.xi[k];
    const double along = C::dot(l.v.data() + C::TAU, d) / C::dot(d, d);
    for (int k = 0; k < 3; k++) {
      l.v[C::DPREV + k] = d[k];
      l.v[C::TAU + k] -= along * d[k];    // tangential
    }
    const double moved[3] = {c * d[0] - s * d[1], s * d[0] + c * d[1], d[2]};
    for (int k = 0; k < 3; k++) {
      l.xj[k] = l.xi[k] + moved[k];
      l.oi[k] = l.oj[k] = k == 2 ? angle / dt : 0.0;
    }
  }
  const std::vector<Link> before = side;
  batched(side, dt, true);
  for (std::size_t l = 0; l < side.size(); l++) {
    const double *t0 = before[l].v.data() + C::TAU, *t1 = side[l].v.data() + C::TAU;
    EXPECT_NEAR(t1[0], c * t0[0] - s * t0[1], 1e-12);
    EXPECT_NEAR(t1[1], s * t0[0] + c * t0[1], 1e-12);
    EXPECT_NEAR(t1[2], t0[2], 1e-12);
    EXPECT_NEAR(side[l].v[C::ET], before[l].v[C::ET], 1e-12);
    EXPECT_NEAR(side[l].v[C::DTAU], 0.0, 1e-12);
    const double *r0 = before[l].v.data() + C::ROT, *r1 = side[l].v.data() + C::ROT;
    EXPECT_NEAR(r1[0], c * r0[0] - s * r0[1], 1e-12);
    EXPECT_NEAR(r1[1], s * r0[0] + c * r0[1], 1e-12);
  }
}
