"""The installed MuJoCo's release: what its grammar lacks or types otherwise, and the
behaviour no grammar row states, applied to the core's tables when the grammar is loaded."""
