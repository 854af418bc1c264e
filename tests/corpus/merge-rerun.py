#!/usr/bin/env python3
"""Merges a partial corpus run into the full report, so a fix can be re-measured on the
scenes it touches without a whole sweep (about 90 minutes):

    target/release/penumbra corpus --only 'a/x.pov,b/*' --out /tmp/rerun/corpus.md
    tests/corpus/merge-rerun.py /tmp/rerun/corpus.md docs/corpus.md

Every scene the partial run measured replaces its row and its gallery entry (and image) in
the full report, and its account of how scenes are judged replaces the old one; a failure
whose scene has since been given a reason in tests/corpus/known-differences.txt takes it; the counts are recomputed from the rows with the
rules of src/study/corpus/report.rs; the header says which scenes were re-measured.
"""
import os, re, shutil, sys

def split(text):
    head, rest = text.split('## Every scene\n\n', 1)
    table, gallery = rest.split('\n## Failures\n', 1)
    rows = [l for l in table.splitlines() if l.startswith('| ') and not l.startswith('| scene ')
            and not l.startswith('| ---')]
    header = [l for l in table.splitlines() if l.startswith('| scene ') or l.startswith('| ---')]
    intro, *entries = re.split(r'\n(?=### )', gallery)
    sections = {e.split('\n', 1)[0][4:].strip(): e for e in entries}
    return head, header, rows, intro, sections

def cells(row):
    return [c.strip() for c in re.split(r'(?<!\\)\|', row)[1:-1]]

def counts(rows, reasons):
    c = {k: 0 for k in ['scenes', 'parse', 'render', 'pp', 'pd', 'fp', 'fd', 'known',
                        'unexplained', 'pfail', 'rfail', 'notyet']}
    for r in rows:
        scene, parses, test, result = cells(r)[:4]
        c['scenes'] += 1
        pixel = test.split(',')[0] == 'pixel'
        if parses == 'yes':
            c['parse'] += 1
        if result in ('pass', '**FAIL**', 'fail, reason known', 'POV-Ray failed'):
            c['render'] += 1
        if result == 'pass':
            c['pp' if pixel else 'pd'] += 1
        if result in ('**FAIL**', 'fail, reason known'):
            c['fp' if pixel else 'fd'] += 1
        if result == 'fail, reason known':
            c['known'] += 1
        if result == '**FAIL**':
            c['unexplained'] += 1
        if result == 'penumbra failed':
            c['pfail'] += 1
            # A failed render counts as a failure, explained when its reason is written down.
            c['known' if scene in reasons else 'unexplained'] += 1
        if result == 'POV-Ray failed':
            c['rfail'] += 1
        if result == 'not measured yet':
            c['notyet'] += 1
    names = [('scenes', 'scenes'), ('parse', 'parse'), ('render', "render (penumbra's K seeds)"),
             ('pp', 'pass, pixel test'), ('pd', 'pass, distribution test'),
             ('fp', 'fail, pixel test'), ('fd', 'fail, distribution test'),
             ('known', 'fail, with the reason written down'), ('unexplained', 'fail, unexplained'),
             ('pfail', 'penumbra failed to render'), ('rfail', 'POV-Ray failed or timed out'),
             ('notyet', 'parse, not measured yet')]
    return '| | scenes |\n| --- | ---: |\n' + ''.join(f'| {n} | {c[k]} |\n' for k, n in names)

def known_reasons():
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'known-differences.txt')
    reasons = {}
    for line in open(path):
        if line.strip() and not line.startswith('#') and '|' in line:
            scene, reason = line.split('|', 1)
            reasons[scene.strip()] = reason.strip()
    return reasons

def explain(row, sections, reasons):
    """A failure without a reason takes the one written down since."""
    c = cells(row)
    if c[3] in ('POV-Ray failed', 'penumbra failed') and c[0] in reasons:
        # Not judged: the reason says why, and the row stays counted as it is.
        reason = reasons[c[0]].replace('|', '\\|')
        if not c[4].startswith(reason):
            c[4] = reason + '; ' + c[4]
        return '| ' + ' | '.join(c) + ' |'
    if c[3] != '**FAIL**' or c[0] not in reasons:
        return row
    reason = reasons[c[0]].replace('|', '\\|')
    c[3] = 'fail, reason known'
    c[4] = reason + '; ' + c[4]
    if c[0] in sections:
        title, rest = sections[c[0]].split('\n', 1)
        sections[c[0]] = title + '\n\nReason: ' + reason + '\n' + rest
    return '| ' + ' | '.join(c) + ' |'

def main():
    partial_path, full_path = sys.argv[1], sys.argv[2]
    p_head, _, p_rows, _, p_sections = split(open(partial_path).read())
    head, header, rows, intro, sections = split(open(full_path).read())
    before = {cells(r)[0]: cells(r)[3] for r in rows}
    # Measured rows, and rows of scenes that parse now but did not before (a new feature):
    # they become "not measured yet" until a run measures them.
    fresh = {cells(r)[0]: r for r in p_rows
             if cells(r)[3] != 'not measured yet' or before.get(cells(r)[0]) == 'does not parse'}
    rows = [fresh.get(cells(r)[0], r) for r in rows]
    gallery_dir = os.path.splitext(full_path)[0]
    partial_gallery = os.path.splitext(partial_path)[0]
    for scene in fresh:
        flat = scene[:-4].replace('/', '_') + '.png'
        sections.pop(scene, None)
        if os.path.exists(os.path.join(gallery_dir, flat)):
            os.remove(os.path.join(gallery_dir, flat))
        if scene in p_sections:
            sections[scene] = p_sections[scene]
            os.makedirs(gallery_dir, exist_ok=True)
            shutil.copy(os.path.join(partial_gallery, flat), os.path.join(gallery_dir, flat))
    # The partial run's binary is the newer one: its account of the tests replaces the old.
    if '## How a scene is judged' in p_head and '## How a scene is judged' in head:
        method = p_head[p_head.index('## How a scene is judged'):]
        head = head[:head.index('## How a scene is judged')] + method
    reasons = known_reasons()
    rows = [explain(r, sections, reasons) for r in rows]
    table_start = head.index('| | scenes |')
    # The table ends at the first line that is not a table row.
    table_end = table_start
    while head.startswith('|', table_end):
        table_end = head.index('\n', table_end) + 1
    table_end -= 1
    head = head[:table_start] + counts(rows, reasons).rstrip('\n') + head[table_end:]
    measured = {s for s in fresh if cells(fresh[s])[3] not in ('does not parse', 'not measured yet')}
    # Earlier merges' scenes stay named.
    earlier = re.search(r'\nRe-measured after fixes[^:]*: ([^\n]*)\.\n', head)
    if earlier:
        measured |= set(earlier.group(1).split(', '))
    measured = sorted(measured)
    note = ('Re-measured after fixes with `--only` and merged by tests/corpus/merge-rerun.py '
            '(which also takes the re-run\'s parse of every scene): '
            + ', '.join(measured) + '.\n\n')
    head = re.sub(r'\nRe-measured after fixes[^\n]*\n', '\n', head)
    head = head.replace('\n| | scenes |', '\n' + note + '| | scenes |', 1)
    order = [cells(r)[0] for r in rows]
    gallery = intro + ''.join('\n' + sections[s] for s in order if s in sections)
    out = head + '## Every scene\n\n' + '\n'.join(header + rows) + '\n\n## Failures\n' + gallery
    open(full_path, 'w').write(out if out.endswith('\n') else out + '\n')
    print(f'{len(measured)} scenes re-measured, {len(fresh)} rows merged into {full_path}')

if __name__ == '__main__':
    main()
