# script-version: 2
# poresph-fields: colour, phase
"""Colour function of the two-fluid model, 0 (gas) to 1 (water)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("colour", "colour")
