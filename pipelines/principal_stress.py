# script-version: 2
# poresph-fields: principal_stress, principal_direction, phase
"""Largest principal stress sigma_1 (tension > 0): diverging map centred on zero."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import field_pipeline  # noqa: E402

options = field_pipeline("principal_stress", "principal_stress", component="X")
