"""One widget per module: the map, its legend, the status lines (and the frontier and tree
panels)."""
