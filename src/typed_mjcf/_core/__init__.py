"""The core: grammar tables, value codecs, names and the element tree.

Imports nothing else of the package (only ``typed_mjcf.assets`` and ``typed_mjcf.types``,
the value types): the layers above extend it through the hooks it offers.
"""
