"""MuJoCo itself: compiling, compiled names and ids, bindings, physics state and pictures."""
