# script-version: 2
# poresph-fields: phase
"""Phases: walls, water, gas, elastic solid and rigid inclusions in fixed categorical colours."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import PHASES, catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("phases", "phase", categorical=PHASES)
