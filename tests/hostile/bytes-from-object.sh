#!/bin/bash
# bytes-from-object.sh OBJECT - the "copy" attack's data (tools/hostile.sh):
# the machine code of OBJECT's .text, its read-only data sections one after
# another, and its relocations, as C initializers for tests/hostile/copy.c.in,
# as a student could write them from the hand-out's compiled reference
# (objcopy, readelf): TEXT, DATA and RELOCS lines, each a list of
# initializers.  A relocation is {offset in .text, offset in DATA or -1,
# the function's name or NULL, addend}.
set -euo pipefail
obj=${1:?usage: bytes-from-object.sh OBJECT}
bytes() { objcopy -O binary --only-section="$1" "$obj" /dev/stdout | od -An -v -tx1 | tr -s ' \n' ' ' |
    sed 's/^ //; s/ $//; s/\([0-9a-f][0-9a-f]\)/0x\1,/g'; }
echo "TEXT $(bytes .text)"
sections=$(objdump -h "$obj" | awk '$2 ~ /^\.rodata/ { print $2 }')
data="" base=0 bases=""
for s in $sections; do
    data="$data $(bytes "$s")"
    bases="$bases $s=$base"
    base=$((base + 16#$(objdump -h "$obj" | awk -v s="$s" '$2 == s { print $3 }')))
done
echo "DATA${data:- 0}"
# symbol -> its section and value (local labels such as .LC1)
objdump -t "$obj" | awk 'NF >= 5 { print $NF, $(NF - 2), $1 }' >"${TMPDIR:-/tmp}/rt-symbols.$$"
echo -n "RELOCS"
readelf -rW "$obj" | awk -v bases="$bases" -v symbols="${TMPDIR:-/tmp}/rt-symbols.$$" '
    function hexnum(s,   v, k) { v = 0; s = tolower(s); sub(/^0x/, "", s); for (k = 1; k <= length(s); k++) v = v * 16 + index("0123456789abcdef", substr(s, k, 1)) - 1; return v }
    BEGIN { n = split(bases, b, " "); for (k = 1; k <= n; k++) { split(b[k], kv, "="); base[kv[1]] = kv[2] }
            while ((getline line < symbols) > 0) { split(line, f, " "); sec[f[1]] = f[2]; val[f[1]] = hexnum(f[3]) } }
    /^Relocation section/ { text = $3 == "'\''.rela.text'\''" ; next }
    text && $3 ~ /^R_X86_64_(PC32|PLT32)$/ {
        name = $5; addend = $6 $7; sub(/^\+/, "", addend); addend = addend == "" ? 0 : addend
        addend = addend ~ /^-/ ? -hexnum(substr(addend, 2)) : hexnum(addend)
        at = hexnum($1)
        if (name in base) printf " {%d, %d, NULL, %d},", at, base[name], addend
        else if (sec[name] in base) printf " {%d, %d, NULL, %d},", at, base[sec[name]] + val[name], addend
        else printf " {%d, -1, \"%s\", %d},", at, name, addend }'
echo
rm -f "${TMPDIR:-/tmp}/rt-symbols.$$"
