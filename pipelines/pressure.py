# script-version: 2
# poresph-fields: pressure, phase
"""Pressure (Pa), sequential colour map, fixed range."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import field_pipeline  # noqa: E402

options = field_pipeline("pressure", "pressure")
