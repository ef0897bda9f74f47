"""Modal screens: help, the file-name prompt, the unsaved-edits question."""
