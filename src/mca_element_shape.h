/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the shape of an element's linked
   pairs (stateless, as spline_laws.h): K = sum_j w_ij x_ij x_ij^T as six
   numbers (xx yy zz xy xz yz) and the displacement sums M = sum_j w dx x^T
   after it (row-major); whether its links span a volume (its smallest
   eigenvalue above 0.1 of the mean: else a fragment, a sheet or a chain,
   whose K^-1 would multiply the pressure's force), its inverse where they
   do, and the gradient H = M K^-1 (mca_element_eos.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_SHAPE_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_SHAPE_H

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaElementShape {
    static constexpr double SPAN = 0.1;    // the smallest eigenvalue / the mean that spans

    // whether the links span a volume: the smallest eigenvalue of K above SPAN of the mean,
    // i.e. K - SPAN tr(K)/3 I positive definite (its leading minors positive: no eigenvalue
    // itself is needed)
    static bool spans(const double *s)
    {
      const double t = SPAN * (s[0] + s[1] + s[2]) / 3.0;
      const double a = s[0] - t, b = s[1] - t, c = s[2] - t;
      const double minor2 = a * b - s[3] * s[3];
      const double det = a * (b * c - s[5] * s[5]) - s[3] * (s[3] * c - s[5] * s[4]) +
          s[4] * (s[3] * s[5] - b * s[4]);
      return a > 0.0 && minor2 > 0.0 && det > 0.0;
    }

    // K^-1 into inv; false: the links span no volume
    static bool invert(const double *s, double *inv)
    {
      const double tr = s[0] + s[1] + s[2];
      if (!(tr > 0.0) || !spans(s)) return false;
      const double det = s[0] * (s[1] * s[2] - s[5] * s[5]) -
          s[3] * (s[3] * s[2] - s[5] * s[4]) + s[4] * (s[3] * s[5] - s[1] * s[4]);
      inv[0] = (s[1] * s[2] - s[5] * s[5]) / det;
      inv[1] = (s[0] * s[2] - s[4] * s[4]) / det;
      inv[2] = (s[0] * s[1] - s[3] * s[3]) / det;
      inv[3] = (s[4] * s[5] - s[3] * s[2]) / det;
      inv[4] = (s[3] * s[5] - s[4] * s[1]) / det;
      inv[5] = (s[3] * s[4] - s[0] * s[5]) / det;
      return true;
    }

    // H = M K^-1, M the nine numbers after K's six in s
    static void gradient(const double *s, const double *inv, double grad[3][3])
    {
      const double kinv[3][3] = {{inv[0], inv[3], inv[4]}, {inv[3], inv[1], inv[5]},
                                 {inv[4], inv[5], inv[2]}};
      for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
          grad[a][b] = s[6 + 3 * a] * kinv[0][b] + s[7 + 3 * a] * kinv[1][b] +
              s[8 + 3 * a] * kinv[2][b];
    }
  };

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
