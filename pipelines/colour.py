# script-version: 2
# poresph-fields: colour, phase
"""Colour function of the two-fluid model, 0 (gas) to 1 (water)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import field_pipeline  # noqa: E402

options = field_pipeline("colour", "colour")
