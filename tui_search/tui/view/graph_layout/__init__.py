"""A graph drawn in terminal cells, without Textual: where its nodes go, what each cell of the
drawing shows, and which node is where (the graph view, :mod:`~tui_search.tui.widgets.
graph_view`, colours and shows it).

* :mod:`~tui_search.tui.view.graph_layout.places`: the nodes' places (the file's, or laid out
  in layers), and buckets to find them by place;
* :mod:`~tui_search.tui.view.graph_layout.canvas`: the places fitted into a box of cells, at
  a zoom, and cut into tiles;
* :mod:`~tui_search.tui.view.graph_layout.labels`: where names and costs go, none over another;
* :mod:`~tui_search.tui.view.graph_layout.raster`: a tile's rows: marks, names, braille roads,
  costs, arrows, an overview's dots;
* :mod:`~tui_search.tui.view.graph_layout.picking`: the node at a cell, near a point, in a
  direction, and Tab's order.
"""
