"""Issue 24's table of the composed kinds without a first one (docs/interaction.md): per prompt,
3 seeds, the catalogue entry's checks, the plausibility checks and the penetration bound
(`motion/pair/resolve.pair_bounds`: IF ≤ 0.10 without contact, mean depth ≤ 3 cm with contact).

    nice -n 5 .venv/bin/python scripts/interaction_kinds_table.py
"""

import numpy as np

from interplay.catalogue.load import catalogue
from interplay.catalogue.schema import specs
from interplay.generators.base import Request, generate_motion
from interplay.generators.interaction.generator import START, InteractionGenerator
from interplay.generators.router import load_generator
from interplay.motion.checks.named import plausibility, run_check
from interplay.motion.pair.resolve import pair_bounds

gen = InteractionGenerator(load_generator(use_spam=False).index)
P = [("one person helps the other get up off the floor", 6, "help_up"), ("two people spar in a boxing match", 6, "spar"),
     ("she hands him a cup", 6, "hand_over"), ("he taps her on the shoulder", 5, "touch"),
     ("one person pats the other on the back", 5, "touch"), ("one person grabs the other's arm", 5, "touch"),
     ("two kids chase each other around", 6, "chase"),
     ("a father carries his little son on his back", 6, "carry"),
     ("a big sister gives her brother a piggyback ride around the garden", 7, "carry"),
     ("a mother leads her little boy by the hand across the park", 7, "lead")]
print("| prompt | kind | its checks passed | plausible | IF (no contact) / depth cm (contact) | within bound |")
print("|---|---|---|---|---|---|")
for prompt, sec, kind in P:
    entry = next(a for a in catalogue().of_kind("interaction") if a.made_by.composition == kind)
    ok_c = ok_p = ok_b = 0
    vals = []
    for seed in (0, 1, 2):
        mo = generate_motion(gen, Request(prompt, 2, float(sec), seed=seed))
        assert mo.plan["composition"]["kind"] == kind
        ok_c += all(run_check(mo.people, s).passed for s in specs(entry))
        contact = kind in ("help_up", "hand_over", "touch", "carry", "lead")
        ok_p += all(r.passed for r in plausibility(mo.people, start=START.get(kind, "standing"), contact=contact))
        pb = pair_bounds(np.asarray(mo.people[0], float), np.asarray(mo.people[1], float), "hands" if contact else "none")
        vals.append(pb["depth_cm"] if contact else max(pb["if"], pb["if_any"]))
        ok_b += pb["ok"]
    names = ", ".join(s["check"] for s in specs(entry))
    print(f"| {prompt} | {kind} | {names}: {ok_c}/3 | {ok_p}/3 | {' '.join(f'{v:.2f}' for v in vals)} | {ok_b}/3 |")
