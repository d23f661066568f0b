"""The order of the gallery (sphinx-gallery's within_subsection_order, named in docs/conf.py): the
textbook problems first, from kinematics to kinetics, then the shipped scenes and the tools. An
example not listed here comes after these, by file name."""

from __future__ import annotations

ORDER = (
    "plot_shaft_disk.py", "plot_dzhanibekov.py", "plot_fast_top.py", "plot_mesh_inertia.py",
    "plot_work_energy.py", "plot_planar.py", "plot_heavy_top.py", "plot_foucault.py", "plot_rocket.py",
    "plot_kepler.py", "plot_j2_orbit.py", "plot_gravity_gradient.py", "plot_cubesat_detumbling.py", "plot_cubesat_pointing.py",
    "plot_work_precision.py", "plot_monte_carlo.py",
)


class TextbookOrder:
    """Sort key of an example's file name: its place in ORDER, then the name."""

    def __init__(self, src_dir: str) -> None:
        self.src_dir = src_dir

    def __call__(self, filename: str) -> tuple[int, str]:
        return (ORDER.index(filename) if filename in ORDER else len(ORDER), filename)

    def __repr__(self) -> str:
        return f"<{self.__class__.__name__}>"
