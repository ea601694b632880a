"""Every run of the suite draws the same hypothesis examples (derandomize): a property test
explores widely, but a CI run on a clean clone must not pass or fail by the draw. Examples
that once failed are kept in the tests as @example."""
from hypothesis import settings

settings.register_profile('suite', derandomize=True)
settings.load_profile('suite')
