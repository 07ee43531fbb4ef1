# asm-from-objdump.awk - objdump -dr --insn-width=16 of one function as GNU
# as lines (tests/hostile/asm-from-object.sh): every byte as it is, each
# 4-byte PC-relative relocation as the symbolic .long that makes it again.
/^ *[0-9a-f]+:\t/ {
    split($0, parts, "\t"); addr = hexnum(substr(parts[1], 1, length(parts[1]) - 1));
    nb = split(parts[2], b, " "); n++; A[n] = addr; N[n] = nb; for (k = 1; k <= nb; k++) B[n, k] = b[k]; next }
/R_X86_64_(PC32|PLT32)/ {
    split($0, r, "\t"); split(r[4], q, ":"); off = hexnum(q[1]); sym = r[5];
    R[off] = sym; PLT[off] = r[4] ~ /PLT32/; next }
END {
    for (i = 1; i <= n; i++) {
        k = 1
        while (k <= N[i]) {
            off = A[i] + k - 1
            if (off in R) {
                s = R[off]; sub(/-0x4$/, "", s); gsub(/\./, "L_", s)
                if (PLT[off]) line = line sprintf("    .long %s@PLT-4\n", s)
                else line = line sprintf("    .long %s - . - 4\n", s)
                k += 4
            } else { line = line sprintf("    .byte 0x%s\n", B[i, k]); k++ }
        }
    }
    printf "%s", line
}
function hexnum(s,   v, k) { v = 0; s = tolower(s); gsub(/[^0-9a-f]/, "", s); for (k = 1; k <= length(s); k++) v = v * 16 + index("0123456789abcdef", substr(s, k, 1)) - 1; return v }
