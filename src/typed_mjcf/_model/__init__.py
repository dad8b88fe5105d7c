"""Operations on a whole model: composition, defaults, validation, keyframes, limits, and
export with its checks (to a string, a folder or a zip)."""
