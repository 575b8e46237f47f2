#!/usr/bin/env python3
"""Print what VTK's own XML reader sees in a .vtu file, as JSON on stdout.

    vtk_dump.py frame.vtu

Output: {"points": n, "cells": n, "point": {name: [tuple, ...]}, "cell": {name: [tuple, ...]}}
with NaN written as null. Exit status 77 when VTK's Python bindings (Debian python3-vtk9) are
missing, 1 when the file cannot be read. Used by tests/cli/vtk_readback_test.cpp.
"""
import json
import math
import sys

try:
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
except ImportError:
    sys.exit(77)


def arrays(data):
    out = {}
    for i in range(data.GetNumberOfArrays()):
        a = data.GetArray(i)
        rows = []
        for t in range(a.GetNumberOfTuples()):
            rows.append([None if math.isnan(x) else x for x in a.GetTuple(t)])
        out[a.GetName()] = rows
    return out


def main():
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(sys.argv[1])
    reader.Update()
    grid = reader.GetOutput()
    if reader.GetErrorCode() != 0 or grid.GetNumberOfPoints() == 0:
        print(f"vtk_dump.py: VTK cannot read {sys.argv[1]}", file=sys.stderr)
        sys.exit(1)
    json.dump({"points": grid.GetNumberOfPoints(), "cells": grid.GetNumberOfCells(),
               "point": arrays(grid.GetPointData()), "cell": arrays(grid.GetCellData())},
              sys.stdout)


if __name__ == "__main__":
    main()
