/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the shape of an element's linked
   pairs (stateless, as spline_laws.h): K = sum_j w_ij x_ij x_ij^T as six
   numbers (xx yy zz xy xz yz) and the displacement sums M = sum_j w dx x^T
   after it (row-major); its smallest eigenvalue, its inverse where its
   links span a volume (the smallest eigenvalue at least 0.1 of the mean:
   else a fragment, a sheet or a chain, whose K^-1 would multiply the
   pressure's force), and the gradient H = M K^-1 (mca_element_eos.h).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_MCA_ELEMENT_SHAPE_H
#define LMP_CLUSTERDYN_MCA_ELEMENT_SHAPE_H

#include <algorithm>
#include <cmath>

namespace LAMMPS_NS {
namespace ClusterDyn {

  struct McaElementShape {
    static constexpr double SPAN = 0.1;    // the smallest eigenvalue / the mean that spans

    // by the trigonometric solution of the characteristic polynomial
    static double smallest_eigenvalue(const double *s)
    {
      const double q = (s[0] + s[1] + s[2]) / 3.0;
      const double off = s[3] * s[3] + s[4] * s[4] + s[5] * s[5];
      const double a = s[0] - q, b = s[1] - q, c = s[2] - q;
      const double p = sqrt((a * a + b * b + c * c + 2.0 * off) / 6.0);
      if (p == 0.0) return q;
      const double det = (a * (b * c - s[5] * s[5]) - s[3] * (s[3] * c - s[5] * s[4]) +
                          s[4] * (s[3] * s[5] - b * s[4])) / (p * p * p);
      const double phi = acos(std::max(-1.0, std::min(1.0, 0.5 * det))) / 3.0;
      return q + 2.0 * p * cos(phi + 2.0 * M_PI / 3.0);
    }

    // K^-1 into inv; false: the links span no volume
    static bool invert(const double *s, double *inv)
    {
      const double tr = s[0] + s[1] + s[2];
      if (!(tr > 0.0) || smallest_eigenvalue(s) < SPAN * tr / 3.0) return false;
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
