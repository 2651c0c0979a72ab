# script-version: 2
# poresph-fields: damage, phase
"""Damage in [0, 1): sequential map; fully damaged particles (damage = 1) in a distinct colour."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("damage", "damage", above_range=[0.0, 0.9, 1.0])
