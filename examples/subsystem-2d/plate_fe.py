"""Finite-element solution of Chernyshev's Fig. 2 plate with SfePy (Debian's python3-sfepy):
10 mm x 100 mm, plane stress, linear elasticity, E = 72 GPa, both end faces clamped, the top
face moved down by 3 % of the height.  Writes the normal stress sigma_yy along the lower and
upper faces (element averages of the first element row, quadratic elements) for a Poisson
ratio of 0.3 (the paper's duralumin) and 1/3 (the triangular lattice):
fe_faces_nu0.3.txt, fe_faces_nu0.333.txt (columns x/mm, sigma_yy lower, upper in MPa,
compression positive)."""
import argparse
import os

import numpy as np
from sfepy.base.base import output
from sfepy.discrete import Equation, Equations, FieldVariable, Integral, Material, Problem
from sfepy.discrete.conditions import Conditions, EssentialBC
from sfepy.discrete.fem import FEDomain, Field
from sfepy.mechanics.matcoefs import stiffness_from_youngpoisson
from sfepy.mesh.mesh_generators import gen_block_mesh
from sfepy.solvers.ls import ScipyDirect
from sfepy.solvers.nls import Newton
from sfepy.terms import Term

WIDTH, HEIGHT, E, STRAIN = 10.0e-3, 100.0e-3, 72e9, 0.03


def solve(nu, nx, ny):
    """sigma_yy (Pa) at the centres of the lower and the upper element rows, and their x."""
    mesh = gen_block_mesh([WIDTH, HEIGHT], [nx + 1, ny + 1], [WIDTH / 2, HEIGHT / 2],
                          name="plate", verbose=False)
    domain = FEDomain("domain", mesh)
    omega = domain.create_region("Omega", "all")
    tol = 1e-3 * HEIGHT / ny
    bottom = domain.create_region("Bottom", f"vertices in y < {tol}", "facet")
    top = domain.create_region("Top", f"vertices in y > {HEIGHT - tol}", "facet")
    field = Field.from_args("fu", np.float64, "vector", omega, approx_order=2)
    u = FieldVariable("u", "unknown", field)
    v = FieldVariable("v", "test", field, primary_var_name="u")
    m = Material("m", D=stiffness_from_youngpoisson(2, E, nu, plane="stress"))
    integral = Integral("i", order=4)
    eq = Equation("balance", Term.new("dw_lin_elastic(m.D, v, u)", integral, omega, m=m, v=v, u=u))
    pb = Problem("plate", equations=Equations([eq]))
    pb.set_bcs(ebcs=Conditions([EssentialBC("clamp", bottom, {"u.all": 0.0}),
                                EssentialBC("press", top, {"u.0": 0.0,
                                                           "u.1": -STRAIN * HEIGHT})]))
    pb.set_solver(Newton({}, lin_solver=ScipyDirect({})))
    state = pb.solve(save_results=False)
    stress = pb.evaluate("ev_cauchy_stress.4.Omega(m.D, u)", mode="el_avg",
                         copy_materials=False)[:, 0, 1, 0]    # sxx, syy, sxy
    centres = domain.get_centroids(2)
    dy = HEIGHT / ny
    lower = np.abs(centres[:, 1] - dy / 2) < 1e-3 * dy
    upper = np.abs(centres[:, 1] - (HEIGHT - dy / 2)) < 1e-3 * dy
    order_l, order_u = np.argsort(centres[lower, 0]), np.argsort(centres[upper, 0])
    return centres[lower, 0][order_l], stress[lower][order_l], stress[upper][order_u]


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--nx", type=int, default=40, help="elements across the width")
    args = parser.parse_args()
    output.set_output(quiet=True)
    here = os.path.dirname(os.path.abspath(__file__))
    for nu in (0.3, 1.0 / 3.0):
        x, lower, upper = solve(nu, args.nx, 10 * args.nx)
        name = os.path.join(here, f"fe_faces_nu{nu:.3g}.txt")
        np.savetxt(name, np.column_stack([x * 1e3, -lower / 1e6, -upper / 1e6]), fmt="%.6g",
                   header=f"SfePy plane stress, E = {E:.3g} Pa, nu = {nu:.4g}, strain {STRAIN}, "
                   f"{args.nx} x {10 * args.nx} Q2 elements\nx_mm sigma_yy_lower_MPa "
                   "sigma_yy_upper_MPa (compression positive)")
        print(f"nu = {nu:.4g}: mean lower {-lower.mean() / 1e6:.1f} MPa, upper "
              f"{-upper.mean() / 1e6:.1f} MPa, E strain = {E * STRAIN / 1e6:.0f} MPa")


if __name__ == "__main__":
    main()
