/* crt0.S (board firmware): the stack at the top of SRAM, .data copied from
 * the ROM, .bss cleared, then main(); linker.ld names the symbols. */
    .section .text.start, "ax"
    .global _start
_start:
    la sp, __stack
    la a0, __data_lma
    la a1, __data_start
    la a2, __data_end
1:  bgeu a1, a2, 2f
    lw t0, 0(a0)
    sw t0, 0(a1)
    addi a0, a0, 4
    addi a1, a1, 4
    j 1b
2:  la a1, __bss_start
    la a2, __bss_end
3:  bgeu a1, a2, 4f
    sw zero, 0(a1)
    addi a1, a1, 4
    j 3b
4:  call main
5:  j 5b
