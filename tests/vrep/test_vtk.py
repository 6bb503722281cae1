#!/usr/bin/env python3
"""The V-model's VTK export read back with VTK's own reader (python3-vtk9): every cell a Bezier
hexahedron (type 79) of the right degrees; every point the double nearest to the exact Bezier
control point (from splinex.extract_bezier, exactly), placed by VTK's own PointIndexFromIJK; and
VTK's evaluation of each cell (with the rational weights) equal to splinex's exact evaluation of
the trivariate within 1e-12.

    PYTHONPATH=build/python /usr/bin/python3 tests/vrep/test_vtk.py build/bin/splinex OUT_DIR
"""
import json
import subprocess
import sys
from fractions import Fraction
from pathlib import Path

import vtk

import splinex


def main():
    cli, out = sys.argv[1], Path(sys.argv[2])
    out.mkdir(parents=True, exist_ok=True)
    checked = 0
    for name in ("torus", "cylinder", "cone", "sphere", "singular-sphere"):
        doc = json.loads(subprocess.run([cli, "vrep", "primitive", name], check=True, capture_output=True, text=True).stdout)
        vtu = out / f"{name}.vtu"
        subprocess.run([cli, "vrep", "export", "-", "--vtk", str(vtu)], input=json.dumps(doc), check=True, capture_output=True, text=True)
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(str(vtu))
        reader.Update()
        grid = reader.GetOutput()
        degrees = grid.GetCellData().GetArray("HigherOrderDegrees")
        vcell = grid.GetCellData().GetArray("vcell")
        # The pieces in the exporter's order: per V-cell, its trivariate's Bezier pieces.
        pieces = []
        for c, cell in enumerate(doc["cells"]):
            T = cell["trivariate"]
            for pc in splinex.extract_bezier(T):
                pieces.append((c, T, pc))
        assert grid.GetNumberOfCells() == len(pieces), (name, grid.GetNumberOfCells(), len(pieces))
        for n, (c, T, pc) in enumerate(pieces):
            assert grid.GetCellType(n) == 79, (name, n, grid.GetCellType(n))
            assert int(vcell.GetTuple1(n)) == c
            S = pc["spline"]
            order = [int(x) for x in S["degrees"]]
            assert list(degrees.GetTuple3(n)) == [float(x) for x in order]
            cellv = grid.GetCell(n)
            ids = cellv.GetPointIds()
            weights = S.get("weights")
            for k in range(order[2] + 1):
                for j in range(order[1] + 1):
                    for i in range(order[0] + 1):
                        m = i + (order[0] + 1) * (j + (order[1] + 1) * k)
                        pid = ids.GetId(vtk.vtkHigherOrderHexahedron.PointIndexFromIJK(i, j, k, order))
                        p = grid.GetPoint(pid)
                        want = [float(Fraction(x)) for x in S["points"][m][:3]]
                        assert list(p) == want, (name, n, (i, j, k), p, want)
                        w = grid.GetPointData().GetArray("RationalWeights").GetTuple1(pid)
                        assert w == (float(Fraction(weights[m])) if weights else 1.0), (name, n, w)
            # VTK's evaluation against the exact one at a few parametric points.
            box = pc["box"]
            for a, b, cc in ((0.25, 0.5, 0.75), (0.5, 0.5, 0.5), (0.1, 0.9, 0.3), (1.0, 0.0, 1.0)):
                x = [0.0, 0.0, 0.0]
                wts = [0.0] * cellv.GetNumberOfPoints()
                cellv.EvaluateLocation(vtk.reference(0), [a, b, cc], x, wts)
                at = [box[d][0] + (box[d][1] - box[d][0]) * Fraction(t) for d, t in enumerate((a, b, cc))]
                exact = [float(v) for v in splinex.evaluate(T, at)[:3]]
                scale = max(1.0, max(abs(v) for v in exact))
                assert max(abs(x[d] - exact[d]) for d in range(3)) <= 1e-12 * scale, (name, n, (a, b, cc), x, exact)
                checked += 1
        print(f"{name}: {grid.GetNumberOfCells()} Bezier hexahedra, {grid.GetNumberOfPoints()} points read back exactly")
    print(f"vtk export: all points exact, {checked} evaluations agree with the exact ones")


if __name__ == "__main__":
    main()
