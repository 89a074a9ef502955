"""QEMU MPS2 board port (``mps2-an385`` Cortex-M3/M0 code, ``mps2-an386`` Cortex-M4F).

Files: ``mps2.h`` (memory map), ``startup_mps2.c`` (vector table, reset), ``mps2.ld`` (linker
script), ``semihost.[ch]`` (ARM semihosting calls), ``uart_cmsdk.[ch]`` (CMSDK APB UART),
``kf_hal_mps2.c`` (the HAL of ``firmware/app/kf_hal.h``).
"""
