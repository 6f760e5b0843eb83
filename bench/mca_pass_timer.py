#!/usr/bin/env python3
"""Patch a copy of the plugin's sources (not the repository's) for bench_mca_passes.sh.

    mca_pass_timer.py SRC [PAD]

SRC: the copy's src/ folder.  pair_mca.cpp gets a wall clock around each of compute()'s parts
(before the passes, the volume pass, the plastic pass, the force pass, after them) for the
steps of a run (not its setup), printed at the style's destruction in us per element-step:

    PASSTIMER us/elem-step: prep P volume V plastic L forces F after A

The totals run over every run of the input (in.plate has one).  PAD > 0: every pair's row of
doubles grows by PAD unused doubles (McaContact::NVALUES), to measure what the bytes streamed
per pair cost.  Stops with an error where an anchor of the patch is no longer in the source.
"""
import re
import sys

if len(sys.argv) not in (2, 3):
    sys.exit(__doc__)
src, pad = sys.argv[1], int(sys.argv[2]) if len(sys.argv) > 2 else 0


def patch(path, edits):
    with open(path) as f:
        text = f.read()
    for old, new in edits:
        if text.count(old) != 1:
            sys.exit(f"mca_pass_timer.py: {path}: anchor not found once: {old[:60]!r}")
        text = text.replace(old, new)
    with open(path, 'w') as f:
        f.write(text)


patch(f"{src}/pair_mca.cpp", [
    ('#include "pair_mca.h"\n',
     '#include "pair_mca.h"\n#include <chrono>\n#include <cstdio>\n'
     'static double T_[5];\nstatic long NA_ = 0;\n'
     'static double now_() { return std::chrono::duration<double>('
     'std::chrono::steady_clock::now().time_since_epoch()).count(); }\n'),
    ('  delete[] pvector;\n',
     '  delete[] pvector;\n  if (NA_) fprintf(stderr, "PASSTIMER us/elem-step: prep %.4f volume %.4f '
     'plastic %.4f forces %.4f after %.4f\\n", 1e6 * T_[0] / NA_, 1e6 * T_[1] / NA_, '
     '1e6 * T_[2] / NA_, 1e6 * T_[3] / NA_, 1e6 * T_[4] / NA_);\n'),
    ('  ev_init(eflag, vflag);\n  const StatePass pass',
     '  const double t0 = now_();\n  if (!update->setupflag) NA_ += atom->nlocal;\n'
     '  ev_init(eflag, vflag);\n  const StatePass pass'),
    ('  if (setting.manybody) volumetric_strain(pass);\n'
     '  if (plasticity.active()) plastic_trial(pass);\n'
     '  StateTally changes;\n  pair_forces(pass, changes);\n',
     '  const double t1 = now_();\n  if (setting.manybody) volumetric_strain(pass);\n'
     '  const double t2 = now_();\n  if (plasticity.active()) plastic_trial(pass);\n'
     '  const double t3 = now_();\n  StateTally changes;\n  pair_forces(pass, changes);\n'
     '  const double t4 = now_();\n'),
    ('  state.end(changes, pvector);\n}\n',
     '  state.end(changes, pvector);\n  if (!update->setupflag) {\n'
     '    const double t[] = {t0, t1, t2, t3, t4, now_()};\n'
     '    for (int k = 0; k < 5; k++) T_[k] += t[k + 1] - t[k];\n  }\n}\n'),
])
if pad > 0:
    path = f"{src}/mca_contact.h"
    with open(path) as f:
        text = f.read()
    text, n = re.subn(r"NVALUES = (\d+)", lambda m: f"NVALUES = {int(m.group(1)) + pad}", text)
    if n != 1:
        sys.exit(f"mca_pass_timer.py: {path}: no single NVALUES")
    with open(path, 'w') as f:
        f.write(text)
