# script-version: 2
# poresph-fields: displacement, phase
"""Displacement along x of the elastic particles (Deptulski 2021 Figs. 5.7d-f, 5.13d-f): diverging
map centred on zero; the range from [visualisation] ranges.displacement, else +-0.2 spacing."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("displacement", "displacement", component="X", solid_field=True)
