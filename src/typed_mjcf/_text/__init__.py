"""XML in and out: parsing, export, and the files and assets a model names."""
