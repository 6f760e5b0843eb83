/* -*- c++ -*- ----------------------------------------------------------
   Cluster-dynamics plugin for LAMMPS: a fingerprint of my atoms (their
   IDs in index order), for data kept per atom index from a force
   evaluation: equal fingerprints, the same atoms in the same slots
   (delete_atoms, create_atoms, sorting and exchanges between runs change
   it; positions are left out: fix deform remaps them before the output).
------------------------------------------------------------------------- */

#ifndef LMP_CLUSTERDYN_ATOMS_FINGERPRINT_H
#define LMP_CLUSTERDYN_ATOMS_FINGERPRINT_H

#include "atom.h"

#include <cstdint>

namespace LAMMPS_NS {
namespace ClusterDyn {

  // FNV-1a over 64-bit words: nlocal, then each atom's ID
  inline std::uint64_t atoms_fingerprint(const Atom *atom)
  {
    std::uint64_t h = 14695981039346656037ULL;
    auto mix = [&h](std::uint64_t word) {
      h ^= word;
      h *= 1099511628211ULL;
    };
    mix((std::uint64_t) atom->nlocal);
    for (int i = 0; i < atom->nlocal; i++) mix((std::uint64_t) atom->tag[i]);
    return h;
  }

}    // namespace ClusterDyn
}    // namespace LAMMPS_NS

#endif
