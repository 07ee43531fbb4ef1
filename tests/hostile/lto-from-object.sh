#!/bin/bash
# lto-from-object.sh OBJECT - the "link-time compile" attack (tools/hostile.sh): the
# .gnu.lto_ sections of an object compiled with -flto (the program of its
# code, and the options it was compiled with) re-emitted as a C file of one
# top-level __asm__ block, which a compile without -flto assembles as they
# are: a link that holds the object then compiles that program, with those
# options, as the user who links.
set -euo pipefail
obj=$1
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
echo '__asm__('
for sec in $(readelf -SW "$obj" | sed -n 's/^ *\[ *[0-9]*\] \(\.gnu\.lto_[^ ]*\) .*/\1/p'); do
    echo "    \".section $sec,\\\"e\\\",@progbits\\n\""
    objcopy --dump-section "$sec=$tmp" "$obj" /dev/null
    od -An -v -tx1 "$tmp" | tr -s ' ' '\n' | grep . | sed 's/^/    ".byte 0x/; s/$/\\n"/'
done
echo '    ".text\n");'
