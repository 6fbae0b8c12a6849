"""Tessera: Dirichlet (Voronoi / Thiessen) tessellations, Delaunay triangulations, window
clipping and ridge grouping of scattered points, as VTK filters.

    from tessera import vtkGeographicProjection

Importing this package loads the VTK modules the filters depend on, so a filter's output can be
handed to any VTK class at once.
"""

from vtkmodules import vtkCommonCore, vtkCommonDataModel, vtkCommonExecutionModel  # noqa: F401

from .tesseraFilters import *  # noqa: F401,F403
