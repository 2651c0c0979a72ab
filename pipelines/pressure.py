# script-version: 2
# poresph-fields: pressure, phase
"""Pressure (Pa), sequential colour map, fixed range."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("pressure", "pressure")
