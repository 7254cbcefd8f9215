#!/usr/bin/env python3
# Usage: scripts/long_functions.py [folder (default src)] [line limit (default 80)]
# Lists C++/GLSL functions longer than a limit (lines from the signature's first line to the
# closing brace). Tracks braces outside comments and strings; a '{' at namespace or class scope
# whose preceding declaration text has a ')' (and is no control statement or initialiser) opens
# a function body. Lambdas inside a function count toward it.
import re, sys, os
root = sys.argv[1] if len(sys.argv) > 1 else 'src'
limit = int(sys.argv[2]) if len(sys.argv) > 2 else 80

def strip(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i); j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (j + 1 - i)); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

results = []
for dp, _, fs in os.walk(root):
    for f in sorted(fs):
        if not f.endswith(('.cpp', '.h', '.hpp', '.glsl', '.comp')): continue
        p = os.path.join(dp, f)
        text = strip(open(p, errors='replace').read())
        text = re.sub(r'(?m)^[ \t]*#.*$', lambda m: ' ' * len(m.group()), text)  # preprocessor lines
        # scope stack: 'ns' (namespace/class/extern/enum: declarations inside) or 'body'
        stack, decl_start, fn = [], 0, None
        for m in re.finditer(r'[{};]', text):
            c, pos = m.group(), m.start()
            if c == '{':
                in_decl_scope = all(s == 'ns' for s in stack)
                head = text[decl_start:pos]
                if in_decl_scope:
                    h = head.strip()
                    if re.search(r'\b(namespace|class|struct|union|enum)\b[^()]*$', h) or h.startswith('extern') or re.search(r'\b(class|struct|union)\b\s+\w+\s*(final)?\s*(:[^()]*)?$', h):
                        stack.append('ns')
                    elif ')' in h and not re.search(r'=\s*$', h) and not re.match(r'^(if|for|while|switch)\b', h):
                        stack.append('body')
                        # the declaration's first non-blank line
                        k = decl_start
                        while k < pos and text[k] in ' \n\t': k += 1
                        fn = (text.count('\n', 0, k) + 1, re.sub(r'\s+', ' ', h)[:110])
                    else:
                        stack.append('init')
                else:
                    stack.append('inner')
                decl_start = pos + 1
            elif c == '}':
                if stack:
                    kind = stack.pop()
                    if kind == 'body' and fn:
                        end = text.count('\n', 0, pos) + 1
                        if end - fn[0] + 1 > limit: results.append((end - fn[0] + 1, f'{p}:{fn[0]}', fn[1]))
                        fn = None
                decl_start = pos + 1
            else:
                if all(s == 'ns' for s in stack): decl_start = pos + 1
for n, where, name in sorted(results, reverse=True):
    print(f'{n:4d}  {where}  {name}')
