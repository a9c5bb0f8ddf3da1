#!/usr/bin/python3
"""A packing's .vtp export opened by VTK's own XML reader, against the packing file.

    /usr/bin/python3 tests/readers/check_vtp_vtk.py packings/seed-1.vtp packings/seed-1.h5

vtkXMLPolyDataReader must read the file without an error, with one point and one vertex cell
per sphere of the packing file (read with h5py), the points equal to the centres, point data
"radius" (the active scalars) equal to the radii and "diameter" to twice them, and the bounds
those of the centres, all to 1e-12 relative (tests/readers/packing_reference.py).

The module is `vtkmodules`, from python3-vtk9 or from python3-paraview, which ships its own VTK
and conflicts with python3-vtk9 on Debian 12 (docs/reading-files.md). Exit 0: ok; 1: the reader
fails or disagrees; 2: usage; 77: no VTK Python module (or h5py).
"""
from packing_reference import Failed, main, need, check_polydata

need(["vtkmodules.vtkIOXML"], "python3-vtk9 or python3-paraview")
import vtkmodules  # noqa: E402
from vtkmodules.vtkCommonCore import vtkCommand, vtkVersion  # noqa: E402
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader  # noqa: E402


def run(vtp, h5):
    reader = vtkXMLPolyDataReader()
    errors = []  # VTK reports errors through events, not exceptions
    reader.AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
    reader.GetExecutive().AddObserver(vtkCommand.ErrorEvent, lambda obj, event: errors.append(event))
    if not reader.CanReadFile(vtp):
        raise Failed(f"vtkXMLPolyDataReader cannot read {vtp} (not a VTK XML PolyData file, or missing)")
    reader.SetFileName(vtp)
    reader.Update()
    if errors or reader.GetErrorCode():
        raise Failed(f"vtkXMLPolyDataReader reports an error on {vtp} (error code {reader.GetErrorCode()})")
    name = f"vtkXMLPolyDataReader (VTK {vtkVersion.GetVTKVersion()}, {vtkmodules.__path__[0]})"
    return check_polydata(reader.GetOutput(), name, vtp, h5)


if __name__ == "__main__":
    main(run, "check_vtp_vtk.py FILE.vtp PACKING.h5")
