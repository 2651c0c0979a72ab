# script-version: 2
# poresph-fields: damage, phase
"""Damage of the elastic solid in [0, 1): sequential map, fully damaged particles (damage = 1) in a
distinct colour; on the slab the other particles in their phases' colours (Pazdniakou 2018 Fig. 11),
in 3D the damaged points (D > 1e-3) alone."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from poresph_views import catalyst_execute, field_pipeline  # noqa: E402,F401 (Catalyst calls catalyst_execute)

options = field_pipeline("damage", "damage", above_range=[0.0, 0.9, 1.0], solid_field=True, shown_above=1e-3)
