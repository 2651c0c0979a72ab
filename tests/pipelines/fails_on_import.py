# script-version: 2
# poresph-fields: pressure
# A pipeline script that raises while Catalyst imports it: the run must stop with this error.
raise RuntimeError("fails_on_import: deliberately broken pipeline")
