# Copyright (C) 2026 the vsph developers.
# SPDX-License-Identifier: GPL-3.0-or-later (see LICENSE).
# scripts/paraview-check.py RUNDIR [DIM [REFDIR]]: run by scripts/paraview-check
# under `xvfb-run -a pvpython`. Opens RUNDIR/snapshots.pvd with ParaView's
# own reader, as the GUI does, and checks what a user of ParaView sees:
#   - the time values: the ones ParaView reports are the pvd's, at round
#     values k t_end / (snapshots) exactly as text (0.2, 0.4, ...), the
#     first and last the t of energy.csv's first and last rows, one per
#     snap_*.vtp in the folder; each file's TimeValue within 5e-10
#     relative of it (the pvd prints 10 significant digits, the file
#     keeps the double);
#   - the point arrays, their names and components (2-D: the vorticity is
#     the scalar vorticity_z, 3-D: the 3-vector vorticity), one vertex per
#     point, no NaN in any array, z components 0 in 2-D, id 0..n-1;
#   - array_descriptions in the FieldData names every array;
#   - free_surface is div_r below the threshold its description gives;
#   - the kinetic energy sum(rho V |u|^2 / 2) (per unit depth in 2-D) against
#     energy.csv's Ek where a row has the snapshot's time (the first and
#     the last), within 1e-10 relative (energy.csv prints 13 significant
#     digits; rho V = m to rounding); between rows, against REFDIR's last
#     row where REFDIR (the third argument) is a run that ends at the
#     snapshot's time, to the same 1e-10, and otherwise no further from
#     the two rows around it than their own difference;
#   - a single .vtp opened alone takes its time from TimeValue.
# Prints what it checked; exits 1 on the first failure.
import csv
import glob
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

from paraview import servermanager
from paraview.simple import OpenDataFile, XMLPolyDataReader

run = sys.argv[1]
dim = int(sys.argv[2]) if len(sys.argv) > 2 else 2
refdir = sys.argv[3] if len(sys.argv) > 3 else None


def fail(msg):
    print("paraview-check: FAILED: " + msg)
    sys.exit(1)


def say(msg):
    print("paraview-check: " + msg)


say("%s, pvpython, %s" % (
    servermanager.vtkSMProxyManager.GetParaViewSourceVersion(), run))

# energy.csv's times and kinetic energies
with open(os.path.join(run, "energy.csv")) as f:
    rows = list(csv.DictReader(f))
t_rows = [float(r["t"]) for r in rows]
ek_rows = {float(r["t"]): float(r["Ek"]) for r in rows}
if refdir:  # a run that ends at one of the snapshots' times
    with open(os.path.join(refdir, "energy.csv")) as f:
        last = list(csv.DictReader(f))[-1]
    ek_rows[float(last["t"])] = float(last["Ek"])

# the pvd as written, and as ParaView reads it
pvd = os.path.join(run, "snapshots.pvd")
# part 0 the fluid's snapshots, part 1 their walls (wall particles and
# images), where the run has any
allparts = [(float(d.get("timestep")), d.get("file"), d.get("part"))
            for d in ET.parse(pvd).getroot().iter("DataSet")]
entries = [(t, f) for t, f, p in allparts if p == "0"]
wall_entries = [(t, f) for t, f, p in allparts if p == "1"]
wall_files = sorted(os.path.basename(p)
                    for p in glob.glob(run + "/walls_*.vtp"))
if [f for _, f in wall_entries] != wall_files:
    fail("the pvd's walls %s, the folder holds %s" % (wall_entries,
                                                      wall_files))
if wall_entries and [t for t, _ in wall_entries] != [t for t, _ in entries]:
    fail("walls not at every snapshot's time: %s" % wall_entries)
reader = OpenDataFile(pvd)
if reader is None:
    fail("ParaView cannot open " + pvd)
times = list(reader.TimestepValues)
files = sorted(os.path.basename(p) for p in glob.glob(run + "/snap_*.vtp"))
if times != [t for t, _ in entries]:
    fail("ParaView's times %s are not the pvd's %s" % (times, entries))
if [f for _, f in entries] != files:
    fail("the pvd lists %s, the folder holds %s" % (entries, files))
m = len(times) - 1
round_times = [float("%.10g" % (t_rows[-1] * k / m)) for k in range(m + 1)]
if m < 2 or times != round_times:
    fail("snapshot times %s are not %s" % (times, round_times))
if times[0] != t_rows[0] or times[-1] != t_rows[-1]:
    fail("the first and last snapshots are not energy.csv's first and last "
         "rows (%r, %r against %r, %r)" % (times[0], times[-1], t_rows[0],
                                           t_rows[-1]))
if any(b <= a for a, b in zip(times, times[1:])):
    fail("times not increasing: %s" % times)
say("%d snapshots at t = %s: ParaView's times are the pvd's, round values, "
    "the first and last energy.csv's (%d rows)"
    % (len(times), ", ".join("%.10g" % t for t in times), len(t_rows)))
if refdir and not any(t in ek_rows and t not in t_rows for t in times):
    fail("%s ends at no snapshot's time" % refdir)

want = {"velocity": 3, "density": 1, "pressure": 1, "volume": 1,
        "mass": 1, "smoothing_length": 1, "div_r": 1, "free_surface": 1,
        "id": 1}
want["vorticity_z" if dim == 2 else "vorticity"] = 1 if dim == 2 else 3
got = {k: reader.PointData[k].GetNumberOfComponents()
       for k in reader.PointData.keys()}
got.pop("material", None)  # two-material contact runs only
if wall_entries:  # the walls' own array
    if got.pop("type", None) != 1:
        fail("the walls carry no one-component type array")
if got != want:
    fail("point arrays %s, want %s" % (sorted(got.items()),
                                       sorted(want.items())))
say("point arrays (name: components) %s" % ", ".join(
    "%s: %d" % kv for kv in sorted(got.items())))

alg = reader.GetClientSideObject()
signed = False
def leaf(obj):
    """The data set inside a part (ParaView nests each part's file)."""
    while obj is not None and obj.IsA("vtkMultiBlockDataSet") and \
            obj.GetNumberOfBlocks() > 0:
        obj = obj.GetBlock(0)
    return obj


nwalls = 0
for t in times:
    alg.UpdateTimeStep(t)
    d = alg.GetOutputDataObject(0)
    if d.IsA("vtkMultiBlockDataSet"):  # the fluid, then its walls
        w = leaf(d.GetBlock(1))
        d = leaf(d.GetBlock(0))
        ty = w.GetPointData().GetArray("type") if w else None
        if (not w or not w.IsA("vtkPolyData") or ty is None or
                w.GetNumberOfVerts() != w.GetNumberOfPoints() or
                any(ty.GetValue(i) not in (1, 2)
                    for i in range(w.GetNumberOfPoints()))):
            fail("t = %g: the walls' block is not points typed 1 or 2" % t)
        nwalls = w.GetNumberOfPoints()
    elif wall_entries:
        fail("t = %g: ParaView shows no walls beside the fluid" % t)
    n = d.GetNumberOfPoints()
    if d.GetClassName() != "vtkPolyData" or n == 0 or d.GetNumberOfVerts() != n:
        fail("t = %g: %s with %d points, %d vertices"
             % (t, d.GetClassName(), n, d.GetNumberOfVerts()))
    fd = d.GetFieldData()
    tv = fd.GetArray("TimeValue").GetValue(0)
    if abs(tv - t) > 5e-10 * abs(t):
        fail("t = %.17g: the file's TimeValue is %.17g" % (t, tv))
    desc = fd.GetAbstractArray("array_descriptions")
    named = set()
    for k in range(desc.GetNumberOfValues()):
        s = desc.GetValue(k)
        if not re.match(r"^[\w, ]+: .+ \(.+\)$", s):
            fail("description not 'names: what (unit)': %r" % s)
        named |= {x.strip() for x in s.split(":")[0].split(",")}
    for k in list(want) + ["Points", "TimeValue"]:
        if k not in named:
            fail("%s is not described in array_descriptions" % k)
    thr = None
    for k in range(desc.GetNumberOfValues()):
        m = re.search(r"div_r < ([0-9.]+)", desc.GetValue(k))
        thr = float(m.group(1)) if m else thr
    pd = d.GetPointData()
    arrays = {k: pd.GetArray(k) for k in want}
    arrays["Points"] = d.GetPoints().GetData()
    for name, a in arrays.items():
        for k in range(a.GetNumberOfTuples() * a.GetNumberOfComponents()):
            if math.isnan(a.GetValue(k)):
                fail("t = %g: NaN in %s" % (t, name))
    pts, vel = arrays["Points"], arrays["velocity"]
    if dim == 2 and any(pts.GetComponent(i, 2) != 0.0 or
                        vel.GetComponent(i, 2) != 0.0 for i in range(n)):
        fail("t = %g: a z component is not 0 in 2-D" % t)
    if any(arrays["id"].GetValue(i) != i for i in range(n)):
        fail("t = %g: id is not 0..n-1" % t)
    divr, surf = arrays["div_r"], arrays["free_surface"]
    if any(surf.GetValue(i) != (divr.GetValue(i) < thr) for i in range(n)):
        fail("t = %g: free_surface is not div_r < %g" % (t, thr))
    rho, vol = arrays["density"], arrays["volume"]
    ek = sum(0.5 * rho.GetValue(i) * vol.GetValue(i) *
             sum(vel.GetComponent(i, c) ** 2 for c in range(3))
             for i in range(n))
    if t in ek_rows:  # a row's time, here or in REFDIR
        ek_ref, said = ek_rows[t], "energy.csv" if t in t_rows else refdir
        if abs(ek - ek_ref) > 1e-10 * abs(ek_ref):
            fail("t = %g: kinetic energy %.13e from the arrays, %.13e in "
                 "%s" % (t, ek, ek_ref, said))
    else:  # between two rows: within their own difference of both
        b = max(k for k in t_rows if k < t)
        a = min(k for k in t_rows if k > t)
        lo, hi = sorted((ek_rows[b], ek_rows[a]))
        if not lo - (hi - lo) <= ek <= hi + (hi - lo):
            fail("t = %g: kinetic energy %.13e from the arrays, rows around "
                 "it %.13e, %.13e" % (t, ek, ek_rows[b], ek_rows[a]))
        said = "rows at %.6g and %.6g: %.12e and" % (b, a, ek_rows[b])
        ek_ref = ek_rows[a]
    w = arrays["vorticity_z" if dim == 2 else "vorticity"]
    lo, hi = w.GetRange(-1 if dim == 3 else 0)
    signed |= dim == 2 and lo < 0 < hi
    say("t = %-12.10g %d points, TimeValue %.17g, Ek %.12e (%s %.12e), "
        "%s %.4g .. %.4g, %d on the free surface"
        % (t, n, tv, ek, said, ek_ref, "vorticity_z" if dim == 2 else
           "|vorticity|", lo, hi,
           sum(int(surf.GetValue(i)) for i in range(n))))
if dim == 2 and not signed:
    fail("vorticity_z never takes both signs: not the signed scalar")
if wall_entries:
    say("walls at every snapshot: part 1 of snapshots.pvd, %d points typed "
        "1 (wall particle) or 2 (image)" % nwalls)
say("every snapshot: one vertex per point, no NaN, %sid 0..n-1, every "
    "array described (array_descriptions), free_surface = div_r < %g, Ek "
    "from the arrays = energy.csv's within 1e-10 at its rows' times (and "
    "the run that ends at a snapshot's), between the rows around it elsewhere"
    % ("z components 0, " if dim == 2 else "", thr))

# one file alone: ParaView takes its time from the FieldData TimeValue
last = os.path.join(run, files[-1])
single = XMLPolyDataReader(FileName=[last])
st = [float(x) for x in single.TimestepValues]
if len(st) != 1 or abs(st[0] - times[-1]) > 5e-10 * abs(times[-1]):
    fail("%s opened alone reports times %s, want %.10g"
         % (files[-1], st, times[-1]))
say("%s opened alone: t = %.17g from its TimeValue" % (files[-1], st[0]))
say("passed")
