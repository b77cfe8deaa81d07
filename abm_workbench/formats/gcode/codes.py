"""G-code words and codes: which the reader knows, what each sets, and a block's words sorted by kind.

G codes belong to groups (LinuxCNC's modal groups: motion, plane, distance mode, ...), each set at
most once in a block; the non-modal ones (dwell, G10, G28, G30, G53, ...) may come together. M codes
are read (tool change, spindle, TCP) or accepted as carrying nothing the engine needs (stops,
coolant, overrides, outputs, modal state, LinuxCNC's user M codes 100-199). Anything else is refused
with the word and the reason.
"""

from ...errors import note
from .cycles import HOLE_CYCLES

#: Letters a block may hold besides G and M (N and O are taken out by the lexer; D, H: the
#: compensation and tool length registers, not used).
LETTERS = set("ABCDFHIJKLPQRSTXYZ")
#: G codes by what they set: each group at most once in a block.
GROUPS = {
    "motion": {0.0, 1.0, 2.0, 3.0, 80.0, *HOLE_CYCLES},
    "plane": {17.0, 18.0, 19.0}, "distance": {90.0, 91.0}, "arc distance": {90.1, 91.1},
    "feed mode": {93.0, 94.0, 95.0}, "units": {20.0, 21.0}, "compensation": {40.0, 41.0, 42.0, 41.1, 42.1},
    "tool length": {43.0, 43.1, 43.4, 43.5, 49.0},
    "coordinate system": {54.0, 55.0, 56.0, 57.0, 58.0, 59.0, 59.1, 59.2, 59.3},
    "path control": {61.0, 61.1, 64.0}, "retract": {98.0, 99.0}, "spindle mode": {96.0, 97.0},
    "non-modal": {4.0, 10.0, 28.0, 28.1, 30.0, 30.1, 53.0, 92.1, 92.2},
}
GROUP_OF = {code: group for group, codes in GROUPS.items() for code in codes}
#: M codes read: tool change, spindle, TCP.
READ_M = {3.0, 4.0, 5.0, 6.0, 61.0, 128.0, 129.0}
#: M codes accepted that carry nothing the engine needs.
IGNORED_M = {0.0, 1.0, 2.0, 30.0, 60.0, 7.0, 8.0, 9.0, 48.0, 49.0, 50.0, 51.0, 52.0, 53.0, 62.0, 63.0, 64.0, 65.0,
             66.0, 67.0, 68.0, 70.0, 71.0, 72.0, 73.0, *map(float, range(100, 200))}
#: Codes refused with their reason.
REFUSED = {("G", 92.0): note("coordinate offsets set by the program (G92) are not read: use G54-G59 and an "
                             "offsets table"),
           ("M", 98.0): note("subprogram calls are not read"), ("M", 99.0): note("subprogram returns are not read")}


class CodeError(ValueError):
    """A word the reader refuses: the word as written and the reason."""

    def __init__(self, word, reason):
        super().__init__(f"{word}: {reason}")
        self.word, self.reason = word, reason


def code_text(letter, value):
    """``G1``, ``G59.1``, ``M6`` as written in messages."""
    return f"{letter}{value:g}"


def sorted_words(words):
    """(G codes, M codes, {letter: Word} of the others) of a block's `words`; CodeError for an unknown or
    repeated word, or two codes setting the same thing."""
    g_codes, m_codes, values, groups = [], [], {}, {}
    for word in words:
        refused = REFUSED.get((word.letter, word.value))
        if refused is not None:
            raise CodeError(word.text, refused)
        if word.letter == "G":
            group = GROUP_OF.get(word.value)
            if group is None:
                raise CodeError(word.text, "not a G code this reader knows (docs/GCODE.md)")
            if group in groups and group != "non-modal":
                raise CodeError(word.text, f"{groups[group]} and {word.text} in one block: both set the {group}")
            groups[group] = word.text
            g_codes.append(word.value)
        elif word.letter == "M":
            if word.value not in READ_M and word.value not in IGNORED_M:
                raise CodeError(word.text, "not an M code this reader knows (docs/GCODE.md)")
            m_codes.append(word.value)
        elif word.letter not in LETTERS:
            raise CodeError(word.text, f"the letter {word.letter} is not read (axes X Y Z and A B C; no U V W, E)")
        elif word.letter in values:
            raise CodeError(word.text, f"{word.letter} is given twice in one block")
        else:
            values[word.letter] = word
    return g_codes, m_codes, values
