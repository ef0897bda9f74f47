"""The maps and their files: the grid and the graph, the formats read and written, and the
generators.

* :mod:`~tui_search.engine.maps.grid`: the map model: size, obstacles, costs, start, goal, moves;
* :mod:`~tui_search.engine.maps.graph`: the graph model: named nodes, roads, start, goals, h;
* :mod:`~tui_search.engine.maps.graph_file`: ``.graph`` files, and the built-in Romania;
* :mod:`~tui_search.engine.maps.source`: the file a grid was read from, and its format;
* :mod:`~tui_search.engine.maps.read`: what every reader shares: ``MapError``, reading safely;
* :mod:`~tui_search.engine.maps.load`: loading a map file of either format;
* :mod:`~tui_search.engine.maps.text`: the text map format;
* :mod:`~tui_search.engine.maps.movingai`: MovingAI ``.map`` files;
* :mod:`~tui_search.engine.maps.layouts`: Pacman layouts (``.lay``), the course's y from below;
* :mod:`~tui_search.engine.maps.terrain`: terrain tables;
* :mod:`~tui_search.engine.maps.scenarios`: MovingAI ``.scen`` files;
* :mod:`~tui_search.engine.maps.write`: saving a grid, changing only the cells edited;
* :mod:`~tui_search.engine.maps.generate`: a recipe made into a map;
* :mod:`~tui_search.engine.maps.mazes`: the generators' algorithms;
* :mod:`~tui_search.engine.maps.recipes`: what ``--generate`` offers, as plain data.
"""
