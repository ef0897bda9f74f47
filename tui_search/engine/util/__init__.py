"""What every layer of the engine may use: nothing here knows of maps or searches.

* :mod:`~tui_search.engine.util.atomic`: writing a file atomically, and an OS error in words;
* :mod:`~tui_search.engine.util.collector`: the cyclic garbage collector paused at start-up;
* :mod:`~tui_search.engine.util.filenames`: a typed file name shown safely, and what is wrong with
  one;
* :mod:`~tui_search.engine.util.frozen`: immutable values written out (cheap to import);
* :mod:`~tui_search.engine.util.numbers`: numbers as the app writes them;
* :mod:`~tui_search.engine.util.prng`: the generators' random numbers, the same everywhere;
* :mod:`~tui_search.engine.util.untrusted`: a file someone else wrote: strict text, shallow JSON,
  TOML.
"""
