# script-version: 2
# poresph-fields: phase, velocity, pressure, density
"""ParaView Live only (poresph run --live HOST:PORT without other pipelines): no images, the
particles are offered to a ParaView GUI that connected with Catalyst > Connect."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from paraview.simple import TrivialProducer  # noqa: E402
from poresph_views import live_options  # noqa: E402

particles = TrivialProducer(registrationName="particles")
options = live_options()
