"""The reference the export checks compare a reader's result with: the packing file (HDF5),
read with h5py alone (docs/reading-files.md), and the comparisons they share.

check_vtp_vtk.py, check_vtp_paraview.py and check_xyz_ase.py import it from their folder.
"""
import sys

SKIP = 77  # ctest's SKIP_RETURN_CODE: the reader's Python module is not installed
RTOL = 1e-12  # the exports are written with %.17g: every reader should get the same doubles back


def need(module_names, package):
    """Imports the modules, or exits 77 naming the Debian package that provides them."""
    try:
        for name in module_names:
            __import__(name)
    except ImportError as e:
        print(f"skip: {e}: {package} is not installed for {sys.executable}")
        sys.exit(SKIP)


need(["h5py", "numpy"], "python3-h5py")
import h5py  # noqa: E402
import numpy as np  # noqa: E402


class Failed(Exception):
    pass


def load_packing(path):
    """centres (N, 3) [m], radii (N) [m], Rs [m] and seed of a packing file."""
    try:
        with h5py.File(path, "r") as f:
            return f["centres"][:], f["radii"][:], float(f["shell/radius"][()]), int(f["provenance/seed"][()])
    except (OSError, KeyError) as e:
        raise Failed(f"{path}: h5py cannot read the packing: {e}")


def close(what, got, want, scale):
    """Raises Failed unless got equals want to RTOL relative to `scale` (an array's magnitude)."""
    got, want = np.asarray(got, dtype=float), np.asarray(want, dtype=float)
    if got.shape != want.shape:
        raise Failed(f"{what}: shape {got.shape}, the packing file's is {want.shape}")
    error = np.abs(got - want)
    if np.any(error > RTOL * scale) or not np.all(np.isfinite(got)):
        k = np.unravel_index(int(np.argmax(error)), error.shape)
        raise Failed(f"{what}: {got[k]!r} at {k}, the packing file says {want[k]!r} (more than {RTOL:g} x {scale:.3g} apart)")


def check_polydata(poly, reader, vtp, h5):
    """The VTK data set a reader made of a .vtp against the packing: points = centres, one vertex
    cell per sphere, point data "radius" (the active scalars) = radii and "diameter" = 2 radii,
    bounds = those of the centres. Returns the ok: line."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    centres, radii, Rs, _ = load_packing(h5)
    n = len(radii)
    if poly is None or poly.GetClassName() != "vtkPolyData":
        raise Failed(f"{reader} made {poly.GetClassName() if poly else 'nothing'} of {vtp}, not a vtkPolyData")
    if poly.GetNumberOfPoints() != n:
        raise Failed(f"{reader} reads {poly.GetNumberOfPoints()} points in {vtp}, {h5} holds {n} spheres")
    if poly.GetNumberOfVerts() != n or poly.GetNumberOfCells() != n:
        raise Failed(f"{reader}: {poly.GetNumberOfVerts()} vertex cells of {poly.GetNumberOfCells()}, expected {n}")
    connectivity = vtk_to_numpy(poly.GetVerts().GetConnectivityArray())
    if not np.array_equal(connectivity, np.arange(n)):
        raise Failed(f"{reader}: the vertex cells are not the points 0 to {n - 1} in order")
    close(f"{reader}: points of {vtp}", vtk_to_numpy(poly.GetPoints().GetData()), centres, Rs)
    data = poly.GetPointData()
    for name, want in (("radius", radii), ("diameter", 2 * radii)):
        array = data.GetArray(name)
        if array is None:
            names = [data.GetArrayName(k) for k in range(data.GetNumberOfArrays())]
            raise Failed(f"{reader}: no point data '{name}' in {vtp} (it has {names})")
        if array.GetNumberOfComponents() != 1 or array.GetDataTypeAsString() != "double":
            raise Failed(f"{reader}: '{name}' has {array.GetNumberOfComponents()} components of "
                         f"{array.GetDataTypeAsString()}, expected 1 of double")
        close(f"{reader}: '{name}' of {vtp}", vtk_to_numpy(array), want, np.max(want))
    scalars = data.GetScalars()
    if scalars is None or scalars.GetName() != "radius":
        raise Failed(f"{reader}: the active scalars of {vtp} are not 'radius'")
    bounds = np.array(poly.GetBounds()).reshape(3, 2)
    close(f"{reader}: bounds of {vtp}", bounds, np.stack([centres.min(axis=0), centres.max(axis=0)], axis=1), Rs)
    return f"{reader} reads {vtp}: {n} points, 'radius' and bounds as in {h5}"


def main(run, usage):
    """Runs run(*paths) -> ok line; FAIL (exit 1) on Failed, usage (exit 2) on wrong arguments."""
    if len(sys.argv) != 3:
        print(f"usage: {usage}", file=sys.stderr)
        sys.exit(2)
    try:
        print("ok: " + run(*sys.argv[1:]))
    except Failed as e:
        print(f"FAIL: {e}")
        sys.exit(1)
