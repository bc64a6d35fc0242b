"""The data card's "Sources considered" section: where more real capture was looked for (issue 25),
what each candidate holds, its licence and what that means for the data and for weights trained
on it, and why it was kept, staged or left out. Written into models/data/README.md by the card."""

SOURCES_CONSIDERED = """\
## Sources considered

Looked for (issue 25) with the search tool (code, docs, pages corpora; repository and path look-ups) and
snapshot fetches, for exercise, seated actions, climbing/crawling, martial arts/boxing, object handling,
everyday gestures and chores, emotions/styles and real two-person interaction beyond dance.
"Snapshot" limits that decided several rows: a fetchable snapshot is at most 500 MiB and lacks files of
4 MiB and more.

| source (where) | what it has | licence | data / weights | outcome |
|---|---|---|---|---|
| CMU Graphics Lab full database, ASF→BVH conversion (una-dinosauria/cmu-mocap, 2,057 BVH files indexed, 120 fps) | every CMU subject: exercise and boxing (13, 14: jumping jacks, squats, stretches, boxing, climb ladder, drink soda), sitting and object handling (15, 111, 113–115: sit in chair, get up, pick up box, walk and carry), chores and emotions pantomimed (79, 80: chopping wood, brushing teeth, crying), martial arts (135, 144), get-ups (140), emotional styles (142), catch/throw and ladders (143), and the **two-person trials**: 18/19 (handshake, pulls, conversation, quarrel, sit together), 20/21 (link arms, high-five, low-five, ring-around-the-rosey, whip, tag), 22/23 (pull up, comfort, shoulder rub, stumble into, pass soda, squats/jumping jacks in turn, arm wrestle, stool threat, keys/wallet throw-catch), 33/34 (football throw-catch) | CMU terms: free for research and commercial products, not resold as data; acknowledge | commercial use allowed for data and weights; keep the acknowledgement | **not ingested**: the snapshot is 789 MB, over the 500 MiB fetch limit; single files are readable only 16 kB at a time (a 2.5 s trial is 231 kB), too few look-ups for more than a sample. The richest gain left: needs a copy in ../shared/data (see below) |
| LeeChunHei/CMU-Mocap-for-AMP-ASE (2,170 CMU trials retargeted to the AMP humanoid, .npy) | CMU, all subjects | CMU terms (no licence file of its own) | as CMU | not ingested: snapshot 779 MB, over the fetch limit |
| Przestr/motion-capture, beemsoft/webxr-handtracking-playground, DragonForgedTheArtist/IClone-CMU-Mocap | CMU subsets already in ../shared/data (cmu-bvh, cmu-salsa, cmu-iclone) | CMU terms | as CMU | already in the main set; nothing new there |
| 414Group/Rotate, a "better-endfield" motions folder, YuanchengLi-Kevin/cmu-mocap-*, cyun9601/CMU-MOCAP-Data, gpdevspace/JEPA_CMU_MoCap, ywchao/baselines, daylanKifky/CMU-Motion-Capture-Database-to-Blender | one or two CMU trials each (18_01/19_01 handshake) or only code that downloads CMU | CMU terms / none | – | nothing worth a source (a single handshake pair at most) |
| ju3tin/bvh (`bvh/SS_TT.bvh`, 1,725 CMU trials of the MotionBuilder-friendly release, flat: 18_01, 19_01, 22_05, 140_01 … listed) | most CMU subjects, the two-person ones included | CMU terms (its README is one line; no licence seen) | as CMU | not ingested: snapshot 742,512,640 bytes (708 MiB), over the fetch limit |
| Shriinivas/cmubvh (READMEFIRST v1.1: the 2010 MotionBuilder-friendly release, whole) | all CMU subjects | CMU terms | as CMU | not ingested: snapshot 1,075,107,840 bytes (1,025 MiB), over the fetch limit |
| kevindaze/EndfieldAnimationImporter (`native/windows-x64/motions`: 18.asf, 19.asf, 18_01, 18_02, 19_01, 19_02.amc — the "better-endfield" folder above) | two handshake pairs in CMU's original Acclaim files | CMU terms | as CMU | not ingested: "no snapshot of that repository can be had here"; the index holds only its README |
| xuebing0229/SullyOS (`public/room3d/motions`) | a manifest naming una-dinosauria @ 09a07f5 `data/022/22_05`, `22_07` + 23's partners and `data/013/13_17.bvh` (the BVHs themselves not committed), and `selected/cmu-18_03 … 22_17.json`: upper-body quaternion tracks retargeted onto its own rig at 30 Hz | CMU terms | as CMU | not ingested: not the capture (re-posed, upper body only), and the fetched snapshot (newest commit) holds no `room3d` folder: the commits with those files are not in it |
| a BioMotionToolbox demo folder (Matlab, `actions/18_01.bvh` + `19_01.bvh`), Neil Lawrence's high-five notebook (CMU 20/21 fetched at run time), AMASS-based two-person loaders (`18_19_Justin`, `20_21_Justin1`, `22_23_justin` SMPL folders) | one handshake pair; download code; AMASS re-fits of the pairs | CMU terms / AMASS licence (non-commercial, no redistribution) | – / research only | nothing fetchable beyond one pair (the toolbox's repository is not named by the index); AMASS re-fits left out for their licence |
| **Bandai Namco Research motion dataset 2** (BandaiNamcoResearchInc/Bandai-Namco-Research-Motiondataset @ 74ead3b) | 2,902 clips, 3 actors: walk, turns, run, wave and raise one/both hands in 7 styles (active, elderly, exhausted, feminine, masculine, normal, youthful) | CC BY-NC 4.0 | **non-commercial only**, for data and weights; attribute | **staged**: the 2,482 clips ../shared/data lacks, `models/data/staged/bandai-namco-2.npz` (opt-in, below) |
| **ReActIdle** (Enekoassets/ReActIdle @ 90b0ac7) | 26 idle standing takes (16 acted: waiting, fidgeting, looking around; 10 genuine: unaware), one performer per id, BVH, 24 fps, 82k frames (57 min); the snapshot lacks 3 acted takes (≥ 4 MiB) | MIT (LICENSE.txt, "Copyright (c) 2025 [RSAIT]") | commercial use allowed for data and weights; keep the notice | **staged**: `models/data/staged/reactidle.npz` (quiet standing: bases for composition, idle requests) |
| glimpse-project/glimpse-training-data | CMU's cgspeed BVH release as zip archives per subject range (`mocap/cmuconvert-mb2-*.zip`) | CMU terms | as CMU | not ingested: every archive is over 4 MiB and absent from the snapshot |
| ubisoft/ubisoft-laforge-lookat, Motorica dance (orangeduck/motorica-retarget), ZeroEGGS | emotional look-at captures, dance, speech gestures | non-commercial research only / not for commercial use | – | left out (research-only terms; dance and gestures are not the families lacking) |
| LAFAN1 (ubisoft/ubisoft-laforge-animation-dataset) | 77 sequences, 5 actors, ~4.6 h: walk, run, jumps, dance, fight, fight-and-sports, obstacles, **ground (crawl, lie, get up)**, sprint, aiming, push and stumble | CC BY-NC-ND 4.0 (license.txt read) | ND: "You do not have permission … to Share Adapted Material" — our retargeted, resampled clips are adapted material | **left out**: the processed data may not be shared (and `lafan1.zip` is over the 4 MiB snapshot limit anyway) |
| NuiSI (souljaboy764/nuisi_dataset) | real two-person skeletons from a depth camera (Nuitrack): wave, handshake, high-five, fist-bumps, clap-fist | **no licence** (README cites MILD, Prasad et al. 2022; no LICENSE file) | all rights reserved by default | **left out**: no permission to redistribute; also 15–19 Kinect-style joints without feet orientation |
| Bütepage et al. HRI data (jbutepage/human_robot_interaction_data) | two-person handshake, waving, rocket and parachute fist-bumps (text skeletons) | **no licence** (README is one line) | all rights reserved | **left out**: no permission |
| SBU Kinect Interaction | two-person Kinect skeletons: approach, depart, push, kick, punch, exchange object, hug, handshake | academic download page (terms not readable here); no repository copy found | research only at best | left out: no redistributable copy, research-only terms |
| InterAct (hku-cg), LongInter, InterHuman, Inter-X, CHI3D, ExPI, DUET, AIR-Act2Act, CMU Panoptic | two-person capture (daily scenarios, kicks, hugs, Lindy hop …) | CC BY-NC-SA 4.0 (InterAct), research-only or unstated (the others) | NC-SA / research only | left out: non-commercial share-alike or research-only; none has a fetchable repository copy of the data |
| 100STYLE (Mason et al.) | 100 locomotion styles (BVH), incl. emotions | CC BY 4.0 as its page states (not read here) | commercial with attribution | not found in any fetchable repository (hosted outside the reachable stores); a good next source for styles |
| Kinematic dataset of actors expressing emotions (Zhang et al. 2020, PhysioNet) | 1,402 takes, 22 actors, 7 emotions over walking, sitting, knocking, lifting, throwing, 125 Hz BVH | PhysioNet **restricted access** (credentialed download) | – | left out: not redistributable; only analysis code in repositories |
| EMOKINE (andres-fr/emokine), Edinburgh locomotion (ELMD), Emotion-Gait, SFU mocap, Georgia Tech lower-limb sets, the Monash sit-to-walk set | emotional dance (one dancer), walks, lower-limb biomechanics, sit-to-walk IMU/EMG | data outside the repositories (Zenodo, lab pages) or lower body only | – | nothing fetchable or nothing full-body |
| HumanAct12, NTU RGB+D, UESTC, HumanML3D/AMASS captions | action sets (exercise, lifting, sitting …) | research only / AMASS licence (non-commercial, no redistribution) | – | left out |
| Mixamo, Reallusion ActorCore samples | many actions | not redistributable | – | left out (brief) |
| KIT whole-body, MoVi, Total Capture, HDM05 full set | exercise, object handling, everyday actions | various (HDM05 CC BY-SA 3.0 — only 11 classes are in a fetchable repository, already in the main set) | – | nothing new reachable |
| CC0 animation libraries ("free BVH", Truebones, outworldz CMU mirror) | CMU re-exports or hand-keyed clips | CMU terms or unclear | – | only CMU again, or no data in a reachable repository |

Named families after this hunt (real single-person minutes in the main set when the hunt was made, by
`label_family`; staged sources add no capture to them except where said):

| family asked for | main set (min) | what the hunt found for it |
|---|---|---|
| exercise and fitness | 5.6 (squats, elbow-to-knee, arm circles, hops, jumps) | CMU 13/14 (jumping jacks, squats, stretches): over the snapshot limit; LAFAN1 ground work: no-derivatives |
| seated and chair actions | 0.0 | CMU 15, 111, 113, 114 (sit on stool/chair, get up): over the snapshot limit; nothing else redistributable |
| climbing and crawling | 0.2 (DeepMimic crawl, roll, get-ups) | CMU 01, 13–15 (ladders, playground), 111 (crawling), 140 (get-ups): over the snapshot limit; cmu-iclone's long climbs are absent (≥ 4 MiB) |
| martial arts and boxing | 3.9 (kicks, punches, swordplay, karate kata) | CMU 13/14 boxing, 135 karate, 144 kicks/blocks: over the snapshot limit |
| object handling | 7.2 (deposit, grab high, throw, basketball) | CMU 115 (pick up box), 113 (walk and carry), 143 (catch and throw): over the snapshot limit |
| everyday gestures and chores | 34.8 (waves, raised hands, bows, calls, traffic signals, washing) | staged: Bandai Namco 2 adds 104 min of waves and raised hands; CMU 79/80 chores (chopping, brushing teeth …): over the snapshot limit |
| emotions and styles | 45.9 (Bandai Namco's 14 non-normal styles) | staged: Bandai Namco 2 adds 7 styles on walk/run/wave/raise (~2.5 h non-normal); CMU 142 (emotional walks): over the snapshot limit; 100STYLE (CC BY): not reachable |
| idle / waiting | (few quiet stretches inside other clips) | staged: ReActIdle, MIT, acted and genuine idle standing |
| real two-person beyond dance | 0 (salsa only, 14 pairs) | CMU 18–23, 33/34 (handshake, high-five, pull, pull up, comfort, pass, arm wrestle, throw-catch): over the snapshot limit in every whole copy found (708–1,025 MiB), at most two pairs elsewhere; NuiSI, Bütepage: no licence; SBU, InterHuman, Inter-X, InterAct: research-only / NC-SA |

What would close the gaps: CMU's own files. A copy of una-dinosauria/cmu-mocap's BVH for subjects 13–15,
18–23, 33/34, 56, 75, 79, 80, 86, 90, 111, 113–115, 135, 137, 140–144 (exercise, boxing, climbing,
sitting, carrying, chores, emotions, martial arts, get-ups, two-person) under ../shared/data would add roughly 2–4 h of single-person
capture and ~0.5 h of real two-person capture in 15+ interaction kinds under CMU's commercial-friendly
terms. The build is ready for the pairs: `cmu_daz` reads that conversion (its MotionBuilder bone names
are Acclaim's bones renamed), and `interplay data build --staged --only cmu-pairs` pairs subject A's and
B's trials (18/19, 20/21, 22/23, 33/34) from `../shared/data/cmu-pairs/0SS/SS_TT.bvh`, labels each with an
interaction kind (`interplay.data.cmu_pairs.KINDS`: handshake, high-five, help up, pull, comfort, hand
over, arm wrestle, throw-catch, walk arm in arm …) and measures its contact windows. Single-person
subjects would need a builder like `cmu-bvh`'s over the same files (not written yet).

Second pass for CMU's two-person trials (issue 25): path look-ups of CMU trial files (18_01, 19_01, 20_01,
22_05, 33_01, 13_29, 140_01, 144_06; `.bvh` or `.amc`) at a repository's root or under `bvh/`, `data/`,
`data/cmu/`, `cmu/`, `motions/`, `actions/`, `018/`, `18/`, `subjects/18/`, `all_asfamc/subjects/18/`;
repository names containing cmu-mocap, cmu_mocap, cmubvh, cmu-bvh, cmu_bvh, cmuconvert, mocap-data, biomotion;
text look-ups of 19_01.amc, 19_01.bvh, 20_01.bvh, 22_01.bvh, 22_07.bvh, 135_01.bvh, 140_04.bvh, 142_01.bvh,
18_19_Justin, cmuconvert-mb2-1; code and pages searches for two-person CMU subsets. Every whole copy of the pairs is over the 500 MiB fetch limit
(una-dinosauria/cmu-mocap 789 MB, ju3tin/bvh 708 MiB, LeeChunHei/CMU-Mocap-for-AMP-ASE 779 MB,
Shriinivas/cmubvh 1,025 MiB; glimpse-project's per-range zips are absent, ≥ 4 MiB), and no repository
that can be fetched was found with both halves of any pair, so nothing was staged (nor CMU's single-person
families: the same copies hold them). `interplay.data.cmu_pairs` reads a copy laid out
as una-dinosauria's `0SS/SS_TT.bvh` (commit 62ac0fb), its newer `data/0SS/SS_TT.bvh` or a flat folder.

### Staged sources (opt-in, `models/data/staged/`)
`interplay data build --staged` reads named snapshots from `/work/.mirror` (fetch step and manifest in
`models/data/staged/README.md`) and writes `models/data/staged/`: its own `index.json`, one npz per
source and a card. The app does not load it (`default_clips()` reads `models/data/index.json` only), so
retrieval, the behaviour fixtures and the trained models are unchanged until a later switch-over moves a
staged source into the main build and regenerates fixtures and evaluations.
"""
