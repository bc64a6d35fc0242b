"""The catalogue of actions: the studio's vocabulary as one data file (`actions.toml`) that every
stage reads. `load.catalogue()` gives the validated entries; `grammar` is the one module with
regular expressions (numbers, counts, sides, sentence structure, and the patterns it compiles
from the catalogue's words); `words` holds the word lists that name no action (`words.toml`),
whose phrases `phrases` finds in a text as words; `match` finds entries for a text through the
MiniLM encoder."""
