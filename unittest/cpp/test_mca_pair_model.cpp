// McaPairModel (mca_pair_model.h): the model of a pair of element types, made once per type
// pair: the weaker element's response, the surfaces' friction, whether they link; both orders
// give the same model.
#include "mca_pair_model.h"

#include "gtest/gtest.h"

#include <cmath>

using LAMMPS_NS::ClusterDyn::McaMaterial;
using LAMMPS_NS::ClusterDyn::McaPairModel;

namespace {

McaMaterial material(double strength, double damage, double mu, double eta, double weld)
{
  McaMaterial m;
  m.bulk = 3.0;
  m.shear = 1.0;
  m.strength = strength;
  m.damage = damage;
  m.friction = mu;
  m.viscous = eta;
  m.weld = weld;
  return m;
}

}    // namespace

TEST(McaPairModel, BothOrdersGiveOneModel)
{
  const McaMaterial a = material(2.0, 1.5, 0.1, 4.0, 9.0), b = material(3.0, 0.0, 0.9, 1.0, 6.0);
  const McaPairModel ab = McaPairModel::of_types(a, b, true), ba = McaPairModel::of_types(b, a, true);
  for (const McaPairModel &m : {ab, ba}) {
    EXPECT_EQ(m.response.strength, 2.0);    // the weaker element
    EXPECT_EQ(m.response.damage, 1.5);
    EXPECT_NEAR(m.friction.mu, 0.3, 1e-15);    // sqrt(0.1 x 0.9)
    EXPECT_NEAR(m.friction.eta, 2.0, 1e-15);   // sqrt(4 x 1)
    EXPECT_EQ(m.friction.weld, 9.0);           // both weld: at the higher pressure
    EXPECT_TRUE(m.links);
  }
}

TEST(McaPairModel, LinkFlagAndUnbreakablePartner)
{
  const McaMaterial strong = material(0.0, 0.0, 0.0, 0.0, 0.0), weak = material(1.0, 0.0, 0.5, 0.0, 2.0);
  const McaPairModel m = McaPairModel::of_types(strong, weak, false);
  EXPECT_FALSE(m.links);
  EXPECT_EQ(m.response.strength, 1.0);    // an element that never breaks leaves the other's
  EXPECT_EQ(m.friction.mu, 0.0);           // a frictionless surface makes the pair frictionless
  EXPECT_EQ(m.friction.weld, 0.0);         // welding needs both
}
