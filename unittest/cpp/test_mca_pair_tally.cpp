// McaPairTally and McaElementShares (mca_pair_tally.h, mca_pair_changes.h): a pair's volume
// change and plastic work go into its elements' rows as its elongation does, i a_j / (a_i + a_j)
// and j a_i / (a_i + a_j) of the whole, j's share only where j's side is tallied here; the
// dissipated works count w (1/2 for a ghost pair with newton off) in the state's tally; empty
// rows take nothing.
#include "mca_pair_tally.h"

#include "gtest/gtest.h"

using LAMMPS_NS::ClusterDyn::McaElementShares;
using LAMMPS_NS::ClusterDyn::McaPairHalves;
using LAMMPS_NS::ClusterDyn::McaPairTally;
using LAMMPS_NS::ClusterDyn::McaVolumeChanges;
using LAMMPS_NS::ClusterDyn::StateTally;
using LAMMPS_NS::ClusterDyn::WORK_DAMAGE;
using LAMMPS_NS::ClusterDyn::WORK_FRICTION;
using LAMMPS_NS::ClusterDyn::WORK_PLASTIC;

namespace {

// three elements' rows of McaVolumeChanges::NCHANGES columns
struct Rows {
  double cells[3][McaVolumeChanges::NCHANGES] = {};
  double *rows[3] = {cells[0], cells[1], cells[2]};
  McaElementShares shares() { return {rows}; }
};

}    // namespace

TEST(McaElementShares, SplitsAsTheElongationByTheOtherHalfsStiffness)
{
  Rows r;
  // a_i = 1, a_j = 3: i takes 3/4, j 1/4 of x = 8
  r.shares().add(McaVolumeChanges::CHANGE_PLASTIC, 2, 0, 8.0, McaPairHalves(1.0, 3.0), true);
  EXPECT_DOUBLE_EQ(r.cells[2][McaVolumeChanges::CHANGE_PLASTIC], 6.0);
  EXPECT_DOUBLE_EQ(r.cells[0][McaVolumeChanges::CHANGE_PLASTIC], 2.0);
  for (int e = 0; e < 3; e++)
    for (int c = 0; c < McaVolumeChanges::NCHANGES; c++)
      if (c != McaVolumeChanges::CHANGE_PLASTIC || e == 1) EXPECT_EQ(r.cells[e][c], 0.0);
  // added, not set; j's side elsewhere: i's share alone
  r.shares().add(McaVolumeChanges::CHANGE_PLASTIC, 2, 0, 8.0, McaPairHalves(1.0, 3.0), false);
  EXPECT_DOUBLE_EQ(r.cells[2][McaVolumeChanges::CHANGE_PLASTIC], 12.0);
  EXPECT_DOUBLE_EQ(r.cells[0][McaVolumeChanges::CHANGE_PLASTIC], 2.0);
  EXPECT_FALSE(McaElementShares());
  EXPECT_TRUE(r.shares());
}

TEST(McaPairTally, VolumeChangesAndPlasticHeatGoToTheRows)
{
  Rows volumes, heat;
  StateTally changes;
  // i = 0, j = 1, a_i = 2, a_j = 6, a ghost pair with newton off: w = 1/2, j's side not here
  const McaPairTally tally{changes, 0.5, volumes.shares(), 0, 1, McaPairHalves(2.0, 6.0), false,
                           heat.shares()};
  tally.volume_change(McaVolumeChanges::CHANGE_DAMAGE, 4.0);
  EXPECT_DOUBLE_EQ(volumes.cells[0][McaVolumeChanges::CHANGE_DAMAGE], 3.0);
  EXPECT_EQ(volumes.cells[1][McaVolumeChanges::CHANGE_DAMAGE], 0.0);
  tally.work(WORK_PLASTIC, 2.0);
  EXPECT_DOUBLE_EQ(changes.work[WORK_PLASTIC], 1.0);
  EXPECT_DOUBLE_EQ(heat.cells[0][0], 1.5);    // the heat is the element's, not weighed by w
  EXPECT_EQ(heat.cells[1][0], 0.0);
  // damage and friction do not heat
  tally.work(WORK_DAMAGE, 2.0);
  tally.work(WORK_FRICTION, 4.0);
  EXPECT_DOUBLE_EQ(changes.work[WORK_DAMAGE], 1.0);
  EXPECT_DOUBLE_EQ(changes.work[WORK_FRICTION], 2.0);
  EXPECT_DOUBLE_EQ(heat.cells[0][0], 1.5);
  // an owned pair: j's shares too
  const McaPairTally owned{changes, 1.0, volumes.shares(), 0, 1, McaPairHalves(2.0, 6.0), true,
                           heat.shares()};
  owned.work(WORK_PLASTIC, 2.0);
  EXPECT_DOUBLE_EQ(heat.cells[0][0], 3.0);
  EXPECT_DOUBLE_EQ(heat.cells[1][0], 0.5);
}

TEST(McaPairTally, EmptyRowsTakeNothing)
{
  StateTally changes;
  const McaPairTally tally{changes, 1.0, McaElementShares(), 0, 1, McaPairHalves(2.0, 6.0), true,
                           McaElementShares()};
  tally.volume_change(McaVolumeChanges::CHANGE_STATE, 4.0);    // no rows to write: no fault
  tally.work(WORK_PLASTIC, 2.0);
  EXPECT_DOUBLE_EQ(changes.work[WORK_PLASTIC], 2.0);
}
