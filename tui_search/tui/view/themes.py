"""The app's colour themes: the default dark, a light one for projectors, and a colour-blind-safe
one.  Each is a Textual theme: its colours reach the widgets only through CSS variables, which the
component classes (``grid-view--*``, ``stats--*``, ...) use, so changing the theme restyles
every widget and no widget names a theme.

The map's colours are the app's own variables (``$map-path``, ``$map-wall``, ...), not Textual's:
a theme that does not set one gets :func:`map_defaults`, worked out from the theme's own colour
system exactly as the map was styled before themes (so the default theme draws as it always did).

Only plain data at import: the command line checks ``--theme`` against :data:`THEMES` without
importing Textual (its headless path must not), and the app builds the Textual objects when it
starts (:func:`tui_search.tui.app.textual_themes`).
"""

# No future import: CONTRIBUTING.md, "Start-up".
from typing import NamedTuple, TypedDict


class Colours(TypedDict, total=False):
    """The base colours of a :class:`textual.theme.Theme` (Textual derives the rest)."""

    primary: str
    secondary: str
    accent: str
    warning: str
    error: str
    success: str
    foreground: str
    background: str
    surface: str
    panel: str


class ThemeSpec(NamedTuple):  # not a frozen dataclass: that compiles six methods at import
    """One theme as data: what the palette and ``--help`` say of it, and its colours (the
    fields of :class:`textual.theme.Theme`, and the CSS variables it sets)."""

    name: str
    title: str  # the palette's "Theme: <title>"
    description: str
    colours: Colours
    variables: dict[str, str]
    dark: bool = True


DEFAULT_THEME = "dark"
#: The fill of a replay's first difference on the maps (``$map-mark``), in every theme.
MARK = "#6600ff"


def ramp(*steps: str, text: str) -> dict[str, str]:
    """The terrain ramp's variables: ``$map-cost-1`` ... (a free cell's cost, the lowest step
    first; each step further from the background in lightness, so the ramp reads in every
    vision and in monochrome), and ``$map-cost-text`` for the glyphs on them."""
    return {**{f"map-cost-{n}": colour for n, colour in enumerate(steps, start=1)},
            "map-cost-text": text}


#: Every theme by name, in the order ``t`` cycles through them.
THEMES: dict[str, ThemeSpec] = {
    t.name: t
    for t in (
        # Textual's own default ("textual-dark"), colour for colour: the look the snapshots pin.
        ThemeSpec("dark", "Dark", "light text on a dark background (the default)",
                  {"primary": "#0178D4", "secondary": "#004578", "accent": "#ffa62b",
                   "warning": "#ffa62b", "error": "#ba3c5b", "success": "#4EBF71",
                   "foreground": "#e0e0e0"}, {}),
        # A projector washes out pale tints and thin dark-on-dark contrast: near-black text on
        # white, and cells filled with strong, dark colours carrying white glyphs.
        ThemeSpec("light", "Light (projector)",
                  "dark text on white, strong cell colours that survive a projector",
                  {"primary": "#1450b8", "secondary": "#0b3a80", "accent": "#b34700",
                   "warning": "#a04000", "error": "#b00020", "success": "#1b7f3b",
                   "foreground": "#111111", "background": "#ffffff", "surface": "#ffffff",
                   "panel": "#e4e9f2"},
                  {"map-free": "#111111 35%", "map-wall": "#3a3a3a",
                   "map-start": "#1b7f3b", "map-start-text": "#ffffff",
                   "map-goal": "#f0d000", "map-goal-text": "#000000",
                   "map-frontier": "#e8a33a", "map-frontier-text": "#000000",
                   "map-expanded": "#8fb8f0", "map-expanded-text": "#0b2a5c",
                   "map-current": "#1450b8", "map-current-text": "#ffffff",
                   "map-path": "#0d5c28", "map-path-text": "#ffffff",
                   # a bidirectional search's backward half in violets (the forward's
                   # frontier is orange here), a cell reached both ways, the meeting
                   "map-back-frontier": "#665588", "map-back-frontier-text": "#ffffff",
                   "map-back-expanded": "#ccaabb", "map-back-expanded-text": "#111111",
                   "map-back-current": "#110033", "map-back-current-text": "#ffffff",
                   "map-both": "#ddffaa", "map-both-text": "#111111",
                   "map-meeting": "#0000aa", "map-meeting-text": "#ffffff",
                   **ramp("#f1e4cc", "#e0c89c", "#c9a66a", "#a8823e", text="#111111"),
                   "footer-key-foreground": "#1450b8", "border-blurred": "#8a94a6"},
                  dark=False),
        # Okabe and Ito's palette for colour-blind viewers: meaning rides on the blue-orange
        # and light-dark axes, which the common colour-vision deficiencies keep, never on red
        # against green.  The path is vermillion on the map and in the tree (success), the
        # expanded cells dark blue (primary), obstacles grey, the start white.  Chosen so that
        # every two kinds of cell stay far apart as protanopes and deuteranopes see them
        # (tests/tui/test_themes.py simulates both).
        ThemeSpec("colour-blind", "Colour-blind safe",
                  "Okabe-Ito colours: blue against orange, never red against green",
                  {"primary": "#0072B2", "secondary": "#005080", "accent": "#56B4E9",
                   "warning": "#F0E442", "error": "#CC79A7", "success": "#D55E00",
                   "foreground": "#e0e0e0"},
                  {"map-wall": "#7a7a7a",
                   "map-start": "#ffffff", "map-start-text": "#000000",
                   "map-goal": "#F0E442", "map-goal-text": "#000000",
                   "map-expanded": "#004a75",
                   "map-current": "#56B4E9", "map-current-text": "#000000",
                   "map-path": "#D55E00", "map-path-text": "#000000",
                   # the backward half in browns and ambers against the forward's blues
                   "map-back-frontier": "#553300", "map-back-frontier-text": "#ffcc66",
                   "map-back-expanded": "#cc9966", "map-back-expanded-text": "#000000",
                   "map-back-current": "#ffee99", "map-back-current-text": "#000000",
                   "map-both": "#000088", "map-both-text": "#ffffff",
                   "map-meeting": "#4477ee", "map-meeting-text": "#000000",
                   **ramp("#3d3526", "#615233", "#8a7440", "#b3984f", text="#e0e0e0")}),
    )
}


def theme_choices() -> str:
    """The names, for messages: ``dark, light, colour-blind``."""
    return ", ".join(THEMES)


def map_defaults(variables: dict[str, str]) -> dict[str, str]:
    """The map's CSS variables from a theme's colour system (``variables``: Textual's
    ``$primary``, ``$success``, ... as generated), for a theme that does not set them."""
    v = variables
    return {
        "map-free": f"{v['foreground']} 30%",
        "map-wall": v["error"],
        "map-start": v["success"], "map-start-text": v["background"],
        "map-goal": "#f0d000", "map-goal-text": "#000000",
        "map-frontier": "#000000", "map-frontier-text": v["foreground"],
        "map-expanded": v["primary-darken-2"], "map-expanded-text": f"{v['foreground']} 70%",
        "map-current": v["primary-lighten-1"], "map-current-text": v["text"],
        "map-path": v["success-darken-2"], "map-path-text": v["success-lighten-2"],
        # A replay's first difference: a violet no state, obstacle or terrain uses, far from
        # every kind of cell in the three themes as protanopes and deuteranopes see it too.
        "map-mark": MARK, "map-mark-text": "#ffffff",
        # A bidirectional search's backward half in browns and oranges (the forward's are
        # black and blues), a cell both halves reached, the best meeting: each far from every
        # other kind of cell as protanopes and deuteranopes see it too (tests/tui/test_themes.py).
        "map-back-frontier": "#443300", "map-back-frontier-text": "#ffcc66",
        "map-back-expanded": "#cc8811", "map-back-expanded-text": "#000000",
        "map-back-current": "#ffdd77", "map-back-current-text": "#000000",
        "map-both": "#88eeff", "map-both-text": "#000000",
        "map-meeting": "#4499bb", "map-meeting-text": "#ffffff",
        **ramp("#3a3020", "#5c4a2a", "#7f6535", "#a68242", text=v["foreground"]),
    }
