/* boot2.S: the RP2040's second stage, the first 256 bytes of flash.
 *
 * The bootrom (datasheet §2.8.1) copies flash's first 256 bytes to the end of SRAM
 * (0x20041F00), checks the CRC32 in the last 4 of them (firmware/tools/boot2_crc
 * appends it at build time) and runs the code in the first 252. Its task is to make
 * the flash readable at 0x10000000 through the XIP SSI (a Synopsys DW_apb_ssi,
 * datasheet §4.10), then to enter the program.
 *
 * This one sets the plainest mode every SPI flash chip knows: the 03h read command,
 * a 24-bit address, one data line, one 32-bit word per access (the XIP cache above
 * the SSI fetches whole lines). SCK = clk_sys / 4: about 1.5 MHz on the ring
 * oscillator the bootrom leaves running, 31.25 MHz once board_init has clk_sys at
 * 125 MHz, under the 50 MHz that 03h reads allow on the Pico's W25Q16JV. A quad
 * mode would fetch several times faster; it depends on the flash chip, this does
 * not.
 *
 * Then the vector table at 0x10000100 (just after these 256 bytes) becomes the
 * processor's: VTOR points at it, SP takes its first word, and the reset handler,
 * its second, runs. The code is position-independent (literals are PC-relative). */
    .syntax unified
    .cpu cortex-m0plus
    .thumb

    .equ XIP_SSI_BASE, 0x18000000
    .equ SSI_CTRLR0, 0x00     /* frame format, transfer mode, frame size */
    .equ SSI_CTRLR1, 0x04     /* NDF: data frames per read, minus one */
    .equ SSI_SSIENR, 0x08     /* enable; the SSI takes a configuration only while off */
    .equ SSI_BAUDR, 0x14      /* SCK divider, even */
    .equ SSI_SPI_CTRLR0, 0xF4 /* what an XIP access sends: command, address length */

    .equ BAUD_DIV, 4
    /* CTRLR0: SPI_FRF (22:21) 0 standard SPI; DFS_32 (20:16) 31: 32-bit frames;
     * TMOD (9:8) 3: EEPROM read (send command and address, then receive) */
    .equ CTRLR0_XIP, (0 << 21) | (31 << 16) | (3 << 8)
    /* SPI_CTRLR0: XIP_CMD (31:24) 03h; INST_L (9:8) 2: an 8-bit instruction;
     * ADDR_L (5:2) 6: 24 address bits; TRANS_TYPE (1:0) 0: instruction and address
     * on one line like the data */
    .equ SPI_CTRLR0_XIP, (0x03 << 24) | (2 << 8) | (6 << 2) | 0

    .equ IMAGE_VECTORS, 0x10000100
    .equ PPB_VTOR, 0xE000ED08

    .section .text, "ax"
    .global boot2_entry
    .type boot2_entry, %function
    .thumb_func
boot2_entry:
    ldr r3, =XIP_SSI_BASE
    movs r1, #0
    str r1, [r3, #SSI_SSIENR]
    movs r1, #BAUD_DIV
    str r1, [r3, #SSI_BAUDR]
    ldr r1, =CTRLR0_XIP
    str r1, [r3, #SSI_CTRLR0]
    ldr r0, =XIP_SSI_BASE + SSI_SPI_CTRLR0 /* beyond a Thumb store's 124-byte offset */
    ldr r1, =SPI_CTRLR0_XIP
    str r1, [r0]
    movs r1, #0                            /* NDF 0: one frame per access */
    str r1, [r3, #SSI_CTRLR1]
    movs r1, #1
    str r1, [r3, #SSI_SSIENR]

    ldr r0, =IMAGE_VECTORS
    ldr r1, =PPB_VTOR
    str r0, [r1]
    ldmia r0!, {r1, r2}                    /* initial SP, reset handler (Thumb bit set) */
    msr msp, r1
    bx r2

    .ltorg
