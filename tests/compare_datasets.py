#!/usr/bin/python3
"""Compares sweetspot datasets variable by variable, bit for bit (global attributes such as
the wall time and the rank count may differ): B.h5 and each further file against A.h5. Prints
"identical" and exits 0 when they all are.

Usage: /usr/bin/python3 tests/compare_datasets.py A.h5 B.h5 [C.h5 ...]
"""
import sys

import h5py
import numpy as np


def names(f):
    out = []
    f.visit(lambda name: out.append(name) if isinstance(f[name], h5py.Dataset) else None)
    return sorted(out)


assert len(sys.argv) >= 3, __doc__
for other in sys.argv[2:]:
    with h5py.File(sys.argv[1], "r") as a, h5py.File(other, "r") as b:
        assert names(a) == names(b), (other, names(a), names(b))
        for name in names(a):
            x, y = a[name][()], b[name][()]
            assert x.dtype == y.dtype and x.shape == y.shape, (other, name)
            assert x.tobytes() == y.tobytes(), f"{other}: {name} differs"
print("identical")
