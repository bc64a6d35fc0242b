"""The reviewer reads an interaction's contact from the catalogue (`contact` on its `pair_*`
entries) the way the interaction generator composes it: the same kinds touch, the same MiniLM
bound finds a kind from its descriptions."""

from __future__ import annotations

from interplay.catalogue.load import catalogue
from interplay.generators.interaction import kinds
from interplay.review.checks import KIND_SIMILARITY, contact_mode


def test_the_catalogue_marks_the_kinds_the_generator_lets_touch():
    touching = {a.made_by.composition for a in catalogue().of_kind("interaction") if a.contact}
    assert touching == set(kinds.CONTACT)
    assert KIND_SIMILARITY == kinds.MIN_SIMILARITY


def test_contact_from_everyday_words_no_list_names():
    assert contact_mode("two friends bump fists") == "hands"          # a high five's description
    assert contact_mode("one person consoles a crying friend") == "hug"
    assert contact_mode("two people walk side by side") == "none"
    assert contact_mode("two people stand and talk") == "none"
