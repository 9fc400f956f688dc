"""tampcli: optimization-based Task and Motion Planning from the command line."""

__version__ = "0.1.0"
