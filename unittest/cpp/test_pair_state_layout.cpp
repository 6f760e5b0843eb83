// PairStateLayout (pair_state_layout.h): a row of doubles saved without the owner's
// within-compute doubles and back; the restart records of one copy and of both copies (from
// before 29 Nov 2026) told apart and read.  SlotPages (slot_pages.h): chunks of pointers, reused
// after a reset.
#include "pair_state_layout.h"
#include "slot_pages.h"

#include "gtest/gtest.h"

#include <vector>

using LAMMPS_NS::tagint;
using LAMMPS_NS::ubuf;
using LAMMPS_NS::ClusterDyn::PairStateLayout;
using LAMMPS_NS::ClusterDyn::SlotPages;

namespace {

// pair mca's layout: 20 doubles and the word; SIG (10), DR (15), DTAU (16) within a compute
PairStateLayout mca_layout()
{
  PairStateLayout layout;
  layout.choose(21, (1 << 10) | (1 << 15) | (1 << 16));
  return layout;
}

std::vector<double> numbered_row(int row, double word)
{
  std::vector<double> v(row);
  for (int k = 0; k < row; k++) v[k] = 100.0 + k;
  v[row - 1] = word;
  return v;
}

}    // namespace

TEST(PairStateLayout, SavesAllButTheWithinComputeDoublesAndTheWordLast)
{
  const PairStateLayout layout = mca_layout();
  ASSERT_EQ(layout.saved(), 18);
  const std::vector<double> row = numbered_row(21, 5.0);
  std::vector<double> kept(18), back(21, -1.0);
  layout.to_saved(row.data(), kept.data());
  EXPECT_EQ(kept[9], 109.0);     // EPL stays at its place
  EXPECT_EQ(kept[10], 111.0);    // ROT follows it: SIG (110) left out
  EXPECT_EQ(kept[13], 114.0);    // HG
  EXPECT_EQ(kept[14], 117.0);    // EHG: DR, DTAU (115, 116) left out
  EXPECT_EQ(kept[17], 5.0);      // the word
  EXPECT_EQ(PairStateLayout::word(kept.data(), 18), 5);
  layout.to_row(kept.data(), back.data());
  for (int k = 0; k < 21; k++) {
    const bool within = k == 10 || k == 15 || k == 16;
    EXPECT_EQ(back[k], within ? 0.0 : row[k]) << k;
  }
}

TEST(PairStateLayout, WithoutWithinComputeDoublesARowIsSavedWhole)
{
  PairStateLayout layout;
  layout.choose(1, 0);    // pair spline: the word only
  ASSERT_EQ(layout.saved(), 1);
  const double row[1] = {-3.0};
  double kept[1], back[1];
  layout.to_saved(row, kept);
  layout.to_row(kept, back);
  EXPECT_EQ(back[0], -3.0);
  EXPECT_EQ(PairStateLayout::word(kept, 1), 3);
}

TEST(PairStateLayout, TellsTheRecordsApart)
{
  const PairStateLayout layout = mca_layout();
  const double marker = PairStateLayout::ONE_COPY, id = ubuf(tagint(1)).d;    // last values
  for (int n : {0, 1, 7}) {
    EXPECT_EQ(layout.record(4 + n * 19, n, marker), PairStateLayout::CURRENT) << n;
    EXPECT_EQ(layout.record(3 + n * 22, n, id), PairStateLayout::BEFORE) << n;
    EXPECT_EQ(layout.record(5 + n * 22, n, marker), PairStateLayout::UNKNOWN) << n;
  }
  // one within-compute double: a pair's record of either kind has the same length, and the
  // marker tells them apart (an ID's bits are not 1.0)
  PairStateLayout one;
  one.choose(4, 1 << 1);
  ASSERT_EQ(one.saved(), 3);
  EXPECT_EQ(one.record(8, 1, marker), PairStateLayout::CURRENT);
  EXPECT_EQ(one.record(8, 1, id), PairStateLayout::BEFORE);
  PairStateLayout spline;
  spline.choose(1, 0);
  EXPECT_EQ(spline.record(4 + 3 * 2, 3, marker), PairStateLayout::CURRENT);
  EXPECT_EQ(spline.record(3 + 3 * 2, 3, id), PairStateLayout::BEFORE);
}

TEST(PairStateLayout, ReadsARecordFromBeforeKeepingTheSmallerIdsCopies)
{
  const PairStateLayout layout = mca_layout();
  const tagint own = 9;
  const tagint partners[3] = {5, 12, 9};    // 9: the atom's own periodic image
  std::vector<double> entries;
  for (int e = 0; e < 3; e++) {
    entries.push_back(ubuf(partners[e]).d);
    const std::vector<double> row = numbered_row(21, e + 1.0);
    entries.insert(entries.end(), row.begin(), row.end());
  }
  entries.push_back(ubuf(own).d);
  ASSERT_EQ(layout.owner_id(entries.data(), 3, PairStateLayout::BEFORE), own);
  tagint partner[3] = {0, 0, 0};
  std::vector<double> kept(3 * 18, 0.0);
  const int n = layout.read(entries.data(), 3, PairStateLayout::BEFORE, own, partner, kept.data());
  ASSERT_EQ(n, 2);    // the pair with 5 is kept by atom 5's record
  EXPECT_EQ(partner[0], 12);
  EXPECT_EQ(partner[1], 9);
  EXPECT_EQ(kept[17], 2.0);         // the second entry's word
  EXPECT_EQ(kept[18 + 17], 3.0);    // the third's
  EXPECT_EQ(kept[10], 111.0);
}

TEST(PairStateLayout, ReadsACurrentRecordAsWritten)
{
  const PairStateLayout layout = mca_layout();
  std::vector<double> entries;
  for (tagint p : {3, 40}) {
    entries.push_back(ubuf(p).d);
    for (int k = 0; k < 18; k++) entries.push_back(p * 1000.0 + k);
  }
  entries.push_back(ubuf(tagint(20)).d);
  EXPECT_EQ(layout.owner_id(entries.data(), 2, PairStateLayout::CURRENT), 20);
  tagint partner[2];
  std::vector<double> kept(36);
  ASSERT_EQ(layout.read(entries.data(), 2, PairStateLayout::CURRENT, 20, partner, kept.data()), 2);
  EXPECT_EQ(partner[0], 3);    // smaller than the atom's ID: kept all the same
  EXPECT_EQ(kept[0], 3000.0);
  EXPECT_EQ(kept[18 + 17], 40017.0);
}

TEST(SlotPages, HandsOutChunksInOrderAndTheSameAfterAReset)
{
  SlotPages pages;
  double **a = pages.get(3), **b = pages.get(4);
  EXPECT_EQ(b, a + 3);
  pages.reset();
  EXPECT_EQ(pages.get(3), a);
  // a chunk that does not fit the rest of the page starts the next one; one larger than a page
  // gets a page of its own
  double **c = pages.get(SlotPages::PAGE - 2);
  EXPECT_NE(c, a + 3);
  double **big = pages.get(SlotPages::PAGE + 10);
  big[SlotPages::PAGE + 9] = nullptr;    // writable to its end
  EXPECT_GE(pages.bytes(), (3.0 * SlotPages::PAGE + 10) * sizeof(double *));
}
