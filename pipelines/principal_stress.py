# script-version: 2
# poresph-fields: principal_stress, principal_direction, phase
"""Largest principal stress sigma_1 (tension > 0): diverging map centred on zero."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("principal_stress", "principal_stress", component="X", solid_field=True)
