# section-from-asm.awk - the "section" attack (tools/hostile.sh): the C file
# of one top-level __asm__ block that asm-from-object.sh writes, turned into
# a variable whose section attribute holds that assembly: GCC writes a
# section's name after ".section" as it is, so a newline in it starts a line
# of assembly, and the word asm appears only inside a string.  "#" ends the
# name's last line (a comment for the assembler), and what GCC adds after it.
NR == 1 { print "/* The compiled reference, as assembly in a section's name (tests/hostile/section-from-asm.awk). */"; next }
/^__asm__\($/ { print "static const int carrier __attribute__((used, section(\".data.carrier\\n\""; next }
/^\);$/ { print "    \".section .data.carrier #\"))) = 0;"; next }
{ print }
