# script-version: 2
# poresph-fields: pressure
# A pipeline script that works for two output steps and raises at the third: the run must stop
# with this error rather than carry on without figures.
from paraview import catalyst

options = catalyst.Options()
options.GlobalTrigger.Frequency = 1


def catalyst_execute(info):
    if info.cycle >= 2:
        raise RuntimeError("fails_later: deliberately broken at output %d" % info.cycle)
