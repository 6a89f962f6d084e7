"""Debian 12's Blender 3.4 runs on the system NumPy 1.24, which removed the `numpy.bool` alias that
Blender's bundled glTF importer still uses (File > Import > glTF 2.0 fails with "module 'numpy'
has no attribute 'bool'"). Enabling the add-on puts the alias back, as NumPy 2 has it again, so an
animator can import a rig's GLB to key its shape keys. Nothing changes where numpy.bool exists."""


def restore_numpy_bool():
    """Sets numpy.bool = numpy.bool_ when NumPy lacks it; returns whether it did."""
    try:
        import numpy
    except ImportError:
        return False
    if "bool" in vars(numpy):
        return False
    numpy.bool = numpy.bool_
    return True
