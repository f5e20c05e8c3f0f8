"""Read the point fields of an LtN VTU or PVTU file (a mesh or particles)."""
import vtk
from vtk.util.numpy_support import vtk_to_numpy


def read_grid(path):
    """The unstructured grid (cells included) of the VTU/PVTU file at path."""
    reader = (vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu")
              else vtk.vtkXMLUnstructuredGridReader())
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def read_vtu(path):
    """Return (points, {field name: values}) of the VTU/PVTU file at path."""
    grid = read_grid(path)
    data = grid.GetPointData()
    return (vtk_to_numpy(grid.GetPoints().GetData()),
            {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i))
             for i in range(data.GetNumberOfArrays())})
