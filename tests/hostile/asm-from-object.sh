#!/bin/bash
# asm-from-object.sh OBJECT - the "assembly" attack (tools/hostile.sh): the
# object's code re-emitted as a C file of one top-level __asm__ block, as a
# student could from the hand-out's compiled reference (objdump -dr): the
# code byte for byte, its relocations as symbolic .long, its read-only data
# sections copied under labels.
set -euo pipefail
obj=${1:?usage: asm-from-object.sh OBJECT}
here=$(dirname "$0")
emit() { sed 's/\\/\\\\/g; s/"/\\"/g; s/.*/    "&\\n"/'; }
echo '/* The compiled reference, re-emitted as assembly (tests/hostile/asm-from-object.sh). */'
echo '__asm__('
{
    echo '.text'
    for f in $(objdump -t "$obj" | awk '$2 == "g" && $3 == "F" && $4 == ".text" { print $NF }'); do
        echo ".globl $f"
        echo ".type $f, @function"
        echo "$f:"
        objdump -dr --insn-width=16 --disassemble="$f" "$obj" | awk -f "$here/asm-from-objdump.awk"
    done
    for sec in $(objdump -h "$obj" | awk '$2 ~ /^\.rodata/ { print $2 }'); do
        label=L_$(echo "$sec" | tr '.' '_')
        echo ".section .rodata"
        echo ".p2align 4"
        echo "$label:"
        objcopy -O binary --only-section="$sec" "$obj" /dev/stdout | od -An -v -tx1 | tr -s ' ' '\n' | grep . |
            sed 's/^/.byte 0x/'
        objdump -t "$obj" | awk -v s="$sec" -v l="$label" '$2 == "l" && $3 == s { print ".set L_" substr($NF, 2) ", " l " + 0x" $1 }'
    done
    echo '.text'
} | emit
echo ');'
