// The link rule of spline_links.h (doc/pair_spline.rst, "Linked pairs"): a linked pair feels
// the law with its tail and breaks for good at r >= Rc a; an unlinked pair feels only
// E = Pi(r) - Pi(a) for r < a; pairs closer than L a link (made at a setup: untallied;
// relink: tallied with the energy jump E_link - E_unlinked).  Morse D, alpha, a closed forms.
#include "spline_links.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace LAMMPS_NS::ClusterDyn;

namespace {

const double D = 0.8, ALPHA = 6.0, A = 1.1, RC = 1.2, L = 1.05;

double pi(double r)
{
  const double e = std::exp(-ALPHA * (r - A));
  return D * (e * e - 2.0 * e);
}
double force(double r)    // -Pi'(r)
{
  const double e = std::exp(-ALPHA * (r - A));
  return 2.0 * ALPHA * D * (e * e - e);
}

// Morse with the cut tail at Rc a, shifted to zero there or not
SplineCoeff cut_coeff(bool shift)
{
  SplineCoeff c{};
  c.d = D;
  c.a = A;
  c.p = ALPHA;
  c.kappa = 1.0;
  MorseLaw::setup(c);
  c.rc = RC * A;
  c.cutsq = c.rc * c.rc;
  c.offset = shift ? pi(c.rc) : 0.0;
  return c;
}

struct Outcome {
  bool interacts;
  int linked;
  double e, fpair;
  StateTally t;
};

// one evaluation of a pair at r, weight w, the linked law's energy and force as the kernel
// passes them (the tail's, shifted)
Outcome eval(const SplineCoeff &c, const LinkCoeff &k, double r, int linked, int making,
             double w = 1.0)
{
  Outcome o{false, linked, 0.0, 0.0, StateTally()};
  o.interacts = SplineLinks::eval<CutTail, true, MorseLaw>(
      c, k, r * r, o.linked, making, w, o.t, pi(r) - c.offset, force(r) / r, o.e, o.fpair);
  return o;
}

LinkCoeff derived(const SplineCoeff &c, int tail)
{
  SplineLinks links;
  links.l = L;
  links.derive<MorseLaw>(c, tail, 1, 2, 3, nullptr);
  const LinkCoeff k = links.coeff[1 * 3 + 2], kt = links.coeff[2 * 3 + 1];
  EXPECT_EQ(k.linksq, kt.linksq);    // symmetric in the type pair
  EXPECT_EQ(k.ebreak, kt.ebreak);
  return k;
}

}    // namespace

TEST(SplineLinks, DerivedThresholds)
{
  const LinkCoeff k = derived(cut_coeff(false), CUT);
  EXPECT_NEAR(k.linksq, L * L * A * A, 1e-14);
  EXPECT_NEAR(k.asq, A * A, 1e-14);
  EXPECT_NEAR(k.ea, -D, 1e-14);
  EXPECT_NEAR(k.ebreak, pi(RC * A), 1e-14);    // unshifted: the energy the link holds at Rc a
  EXPECT_NEAR(derived(cut_coeff(true), CUT).ebreak, 0.0, 1e-14);        // shifted: none
  EXPECT_NEAR(derived(cut_coeff(false), WAGNER).ebreak, 0.0, 1e-14);    // smooth tails: none
  SplineLinks links;
  EXPECT_FALSE(links.on());
  links.l = L;
  EXPECT_TRUE(links.on());
  EXPECT_EQ(links.making(), MAKE_NONE);
  links.relink = 1;
  EXPECT_EQ(links.making(), MAKE_AGAIN);
}

TEST(SplineLinks, LinkedPairFeelsTheLawUntilRcThenBreaks)
{
  const SplineCoeff c = cut_coeff(false);
  const LinkCoeff k = derived(c, CUT);
  const double r_in = RC * A * (1.0 - 1e-12);
  const Outcome in = eval(c, k, r_in, 1, MAKE_AGAIN);
  EXPECT_TRUE(in.interacts);
  EXPECT_EQ(in.linked, 1);
  EXPECT_NEAR(in.e, pi(r_in), 1e-14);
  EXPECT_NEAR(in.fpair * r_in, force(r_in), 1e-14);
  EXPECT_FALSE(in.t.any());
  // at r = Rc a: broken, no interaction, the jump -Pi(Rc a) tallied with weight w
  const Outcome out = eval(c, k, RC * A, 1, MAKE_AGAIN, 0.5);
  EXPECT_FALSE(out.interacts);
  EXPECT_EQ(out.linked, 0);
  EXPECT_DOUBLE_EQ(out.t.broken, 0.5);
  EXPECT_NEAR(out.t.ejump, -0.5 * pi(RC * A), 1e-14);
  // and for good: back inside Rc a (beyond a) it no longer attracts
  EXPECT_FALSE(eval(c, k, 1.1 * A, out.linked, MAKE_NONE).interacts);
}

TEST(SplineLinks, UnlinkedPairOnlyRepels)
{
  const SplineCoeff c = cut_coeff(false);
  const LinkCoeff k = derived(c, CUT);
  for (double r : {0.9 * A, 0.99 * A}) {
    const Outcome o = eval(c, k, r, 0, MAKE_NONE);
    EXPECT_TRUE(o.interacts);
    EXPECT_EQ(o.linked, 0);
    EXPECT_NEAR(o.e, pi(r) + D, 1e-13);    // Pi(r) - Pi(a)
    EXPECT_GT(o.fpair, 0.0);
    EXPECT_NEAR(o.fpair * r, force(r), 1e-12 * std::fabs(force(r)));
  }
  EXPECT_FALSE(eval(c, k, A, 0, MAKE_NONE).interacts);
  EXPECT_FALSE(eval(c, k, 1.01 * A, 0, MAKE_NONE).interacts);
}

TEST(SplineLinks, PairsCloserThanLLink)
{
  const SplineCoeff c = cut_coeff(false);
  const LinkCoeff k = derived(c, CUT);
  // at a setup (MAKE_INITIAL): linked, nothing tallied
  const Outcome setup = eval(c, k, 1.03 * A, 0, MAKE_INITIAL);
  EXPECT_TRUE(setup.interacts);
  EXPECT_EQ(setup.linked, 1);
  EXPECT_NEAR(setup.e, pi(1.03 * A), 1e-14);
  EXPECT_FALSE(setup.t.any());
  EXPECT_DOUBLE_EQ(setup.t.ejump, 0.0);
  // relink between a and L a: the whole binding energy Pi(r) is released
  const Outcome weld = eval(c, k, 1.03 * A, 0, MAKE_AGAIN, 0.5);
  EXPECT_EQ(weld.linked, 1);
  EXPECT_DOUBLE_EQ(weld.t.formed, 0.5);
  EXPECT_NEAR(weld.t.ejump, 0.5 * pi(1.03 * A), 1e-14);
  // relink inside a: E_link - E_unlinked = Pi(r) - (Pi(r) - Pi(a)) = Pi(a) = -D
  const Outcome close = eval(c, k, 0.95 * A, 0, MAKE_AGAIN);
  EXPECT_EQ(close.linked, 1);
  EXPECT_NEAR(close.t.ejump, -D, 1e-13);
  // at and beyond L a: no link
  const Outcome far = eval(c, k, L * A * (1.0 + 1e-12), 0, MAKE_AGAIN);
  EXPECT_EQ(far.linked, 0);
  EXPECT_FALSE(far.interacts);
  EXPECT_FALSE(far.t.any());
}
