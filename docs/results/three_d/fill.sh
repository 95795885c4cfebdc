#!/bin/bash
# Rebuilds README.md's two tables from the records (table.py).
cd "$(dirname "$0")"
/usr/bin/python3 - <<'PY'
import re
import subprocess
out = subprocess.run(["/usr/bin/python3", "table.py"], capture_output=True, text=True, check=True)
t = out.stdout.strip().split('\n\n')
rows1 = '\n'.join(t[0].split('\n')[2:])
rows2 = '\n'.join(t[1].split('\n')[2:])
s = open('README.md').read()
head, body = s.split('## Result', 1)
body = re.sub(r'(\| case \|.*\n\|---.*\n)(?:\|.*\n)*', lambda m: m.group(1) + rows1 + '\n', body, count=1)
body = re.sub(r'(\| group \|.*\n\|---.*\n)(?:\|.*\n)*', lambda m: m.group(1) + rows2 + '\n', body, count=1)
open('README.md', 'w').write(head + '## Result' + body)
PY
