/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: the keywords each command takes.
   One table per command: its parser accepts these and no other (KeywordSet),
   its "unknown keyword" error lists them, and the documentation coverage test
   (unittest/python/test_doc_coverage.py) reads this file and checks that the
   command's page gives each in Syntax, each dimensioned one in its Units
   section and each optional one in its Default section.  Keep one entry a
   line: {"name", values, "dimension", OPTIONAL|REQUIRED}, with values the
   count of values after the keyword (-1: a list up to the next keyword) and
   dimension the kind of LAMMPS unit of its values ("" when it has none).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_STYLE_KEYWORDS_H
#define LMP_CLUSTERDYN_STYLE_KEYWORDS_H

#include <vector>

namespace LAMMPS_NS {
namespace ClusterDyn {

  enum KeywordUse { REQUIRED, OPTIONAL };

  struct StyleKeyword {
    const char *name;
    int values;
    const char *dimension;
    KeywordUse use;
  };

  using KeywordTable = std::vector<StyleKeyword>;

  namespace Keywords {

    // doc: pair_spline (pair_style NAME/spline TAIL ... keywords)
    inline const KeywordTable SPLINE_STYLE = {
        {"start", 1, "", OPTIONAL},
        {"chain", 1, "", OPTIONAL},
        {"link", 1, "", OPTIONAL},
        {"relink", 1, "", OPTIONAL},
    };

    // doc: pair_spline (pair_coeff I J D alpha a keywords)
    inline const KeywordTable SPLINE_COEFF = {
        {"kappa", 1, "", OPTIONAL},
        {"rc", 1, "", OPTIONAL},
        {"rs", 1, "", OPTIONAL},
    };

    // doc: pair_mca (pair_style mca keywords)
    inline const KeywordTable MCA_STYLE = {
        {"fraction", 1, "", REQUIRED},
        {"tolerance", 1, "", OPTIONAL},
        {"manybody", 1, "", OPTIONAL},
        {"plane", 1, "", OPTIONAL},
    };

    // doc: pair_mca (pair_coeff I I: a material)
    inline const KeywordTable MCA_MATERIAL = {
        {"bulk", 1, "pressure", REQUIRED},
        {"shear", 1, "pressure", REQUIRED},
        {"young", 1, "pressure", REQUIRED},
        {"poisson", 1, "", REQUIRED},
        {"shock", 4, "density velocity", REQUIRED},
        {"strength", 1, "pressure", OPTIONAL},
        {"damage", 1, "pressure", OPTIONAL},
        {"spall", 3, "pressure 1/time", OPTIONAL},
        {"yield", 1, "pressure", OPTIONAL},
        {"hardening", 1, "pressure", OPTIONAL},
        {"friction", 1, "", OPTIONAL},
        {"viscous", 1, "pressure/velocity", OPTIONAL},
        {"weld", 1, "pressure", OPTIONAL},
        {"bulk_viscosity", 2, "", OPTIONAL},
        {"hourglass", 1, "", OPTIONAL},
    };

    // doc: pair_mca (pair_coeff I J: a pair of types; link also after a material)
    inline const KeywordTable MCA_TYPES = {
        {"link", 1, "", OPTIONAL},
        {"segments", -1, "", OPTIONAL},
    };

    // doc: pair_mca (pair_coeff I J segments mu0 keywords)
    inline const KeywordTable MCA_SEGMENTS = {
        {"viscous", 1, "pressure/velocity", OPTIONAL},
        {"limit", 1, "pressure", OPTIONAL},
        {"roughness", 7, "distance", OPTIONAL},
    };

    // doc: fix_viscous_relative
    inline const KeywordTable VISCOUS_RELATIVE = {
        {"mode", 1, "", OPTIONAL},
        {"weight", 1, "", OPTIONAL},
        {"cutoff", 1, "distance", OPTIONAL},
    };

    // doc: fix_descent_normalized
    inline const KeywordTable DESCENT_NORMALIZED = {
        {"decay", 1, "", OPTIONAL},
        {"min", 1, "distance", OPTIONAL},
        {"inertia", 2, "", OPTIONAL},
    };

    // doc: compute_dust
    inline const KeywordTable DUST = {
        {"cutoff", 1, "distance", OPTIONAL},
        {"maxsize", 1, "", OPTIONAL},
        {"links", 0, "", OPTIONAL},
        {"rows", 1, "", OPTIONAL},
    };

    // doc: compute_free_surface
    inline const KeywordTable FREE_SURFACE = {
        {"axis", 1, "", OPTIONAL},
        {"face", 1, "", OPTIONAL},
        {"minsize", 1, "", OPTIONAL},
    };

    // doc: compute_pair_params
    inline const KeywordTable PAIR_PARAMS = {
        {"mass", 1, "mass", OPTIONAL},
        {"rc", 1, "", OPTIONAL},
        {"lattice", 1, "", OPTIONAL},
        {"u", -1, "velocity", OPTIONAL},
    };

  }    // namespace Keywords

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
