#!/usr/bin/pvpython
"""A packing's .vtp export opened by ParaView (paraview.simple), against the packing file.

    pvpython tests/readers/check_vtp_paraview.py packings/seed-1.vtp packings/seed-1.h5

ParaView chooses the reader itself (OpenDataFile, as File > Open does); the data it produces,
fetched to the client (servermanager.Fetch), must hold one point and one vertex cell per sphere
of the packing file (read with h5py), the points equal to the centres, point data "radius"
(the active scalars) equal to the radii and "diameter" to twice them, and the bounds those of
the centres, all to 1e-12 relative (tests/readers/packing_reference.py); ParaView's own data
information must give the same number of points and the same bounds.

Run by pvpython (Debian python3-paraview or paraview); /usr/bin/python3 imports paraview.simple
too on Debian 12. Exit 0: ok; 1: ParaView cannot open the file or disagrees; 2: usage; 77:
ParaView's Python modules (or h5py) are not installed.
"""
import sys
import os

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # packing_reference (pvpython, too)
from packing_reference import Failed, main, need, check_polydata, close, load_packing  # noqa: E402

need(["paraview.simple"], "python3-paraview (pvpython)")
import paraview  # noqa: E402
from paraview import servermanager, simple  # noqa: E402


def run(vtp, h5):
    try:
        source = simple.OpenDataFile(vtp)
    except RuntimeError as e:  # "File not readable", "No reader found"
        raise Failed(f"ParaView cannot open {vtp}: {e}")
    if source is None:
        raise Failed(f"ParaView found no reader for {vtp}")
    source.UpdatePipeline()
    name = f"ParaView {paraview.__version__} ({source.GetXMLName()})"
    # A file ParaView opens but cannot parse (cut short, say) gives its errors on the log and an
    # empty data set: the count below fails then.
    poly = servermanager.Fetch(source)
    line = check_polydata(poly, name, vtp, h5)
    info = source.GetDataInformation()
    centres, radii, Rs, _ = load_packing(h5)
    if info.GetNumberOfPoints() != len(radii):
        raise Failed(f"{name}: its data information says {info.GetNumberOfPoints()} points, {h5} holds {len(radii)}")
    close(f"{name}: bounds in its data information", info.GetBounds(), poly.GetBounds(), Rs)
    return line


if __name__ == "__main__":
    main(run, "pvpython check_vtp_paraview.py FILE.vtp PACKING.h5")
