/* boot2.S: the RP2040's second stage, the first 256 bytes of flash.
 *
 * The bootrom (datasheet §2.8.1) copies flash's first 256 bytes to the end of SRAM
 * (0x20041F00), checks the CRC32 in the last 4 of them (firmware/tools/boot2_crc
 * appends it at build time) and runs the code in the first 252. Its task is to make
 * the flash readable at 0x10000000 through the XIP SSI (a Synopsys DW_apb_ssi,
 * datasheet §4.10), then to enter the program.
 *
 * It sets the fastest read the Pico's flash (a Winbond W25Q16JV) has, as the
 * chip's SDK does: Fast Read Quad I/O (EBh) in continuous read mode. Each access
 * the XIP cache makes then sends no command, only the address and the mode bits on
 * four lines, waits four clocks and takes the 32-bit word back on four lines: 20
 * clocks a word, where the 03h read took 64. SCK = clk_sys / 4: about 1.5 MHz on
 * the ring oscillator the bootrom leaves running, 31.25 MHz once board_init has
 * clk_sys at 125 MHz.
 *
 * 1. The pads: SCLK at 8 mA and fast slew, the data pads' Schmitt triggers off
 *    (less delay at these clocks), as the SDK sets them.
 * 2. The flash's quad lines: its status register 2's QE bit makes WP and HOLD into
 *    IO2 and IO3. It is non-volatile; where it is clear, a write enable (06h) and a
 *    status write (01h) set it, status register 1 written back as read (the SDK
 *    writes 0 there, which clears any block protection), and status register 1's
 *    BUSY bit is polled until the write is done. Where it is set, the flash is not
 *    written.
 * 3. One EBh read at address 0 with mode bits A0h (M5..4 = 10b), after which the
 *    flash takes the next read without its command; then the SSI is set to send
 *    only the address and those mode bits (INST_L 0: {address, XIP_CMD}).
 *
 * Then the vector table at 0x10000100 (just after these 256 bytes) becomes the
 * processor's: VTOR points at it, SP takes its first word, and the reset handler,
 * its second, runs. The code is position-independent (literals are PC-relative).
 * tests/test_boot2.c runs it on a model of the SSI and the flash. */
    .syntax unified
    .cpu cortex-m0plus
    .thumb

    .equ PADS_QSPI_BASE, 0x40020000
    .equ PADS_SCLK, 0x04
    .equ PADS_SD0, 0x08       /* SD1..SD3 follow, 4 bytes apart */
    .equ PADS_SCLK_8MA_FAST, (2 << 4) | 1 /* DRIVE (5:4) 2: 8 mA; SLEWFAST (0) */
    .equ PADS_SCHMITT, 1 << 1

    .equ XIP_SSI_BASE, 0x18000000
    .equ SSI_CTRLR0, 0x00     /* frame format, frame size, transfer mode */
    .equ SSI_CTRLR1, 0x04     /* NDF: data frames per read, minus one */
    .equ SSI_SSIENR, 0x08     /* enable; the SSI takes a configuration only while off */
    .equ SSI_BAUDR, 0x14      /* SCK divider, even */
    .equ SSI_SR, 0x28         /* status: BUSY (0), TFE (2): transmit FIFO empty */
    .equ SSI_DR0, 0x60        /* the FIFOs */
    .equ SSI_RX_SAMPLE_DLY, 0xF0
    .equ SSI_SPI_CTRLR0, 0xF4 /* what an XIP or EEPROM read sends: command, address, wait */
    .equ SR_BUSY, 1 << 0
    .equ SR_TFE, 1 << 2

    .equ BAUD_DIV, 4
    /* CTRLR0 for commands a byte at a time: SPI_FRF (22:21) 0, standard SPI; DFS_32
     * (20:16) 7: 8-bit frames; TMOD (9:8) 0: transmit and receive */
    .equ CTRLR0_BYTES, (0 << 21) | (7 << 16) | (0 << 8)
    /* for reads: SPI_FRF 2, quad; DFS_32 31: 32-bit frames; TMOD 3: EEPROM read
     * (send command and address, then receive) */
    .equ CTRLR0_QUAD_READ, (2 << 21) | (31 << 16) | (3 << 8)
    /* SPI_CTRLR0 fields: XIP_CMD (31:24), WAIT_CYCLES (15:11), INST_L (9:8), ADDR_L
     * (5:2, in 4-bit units: 8 is the 24 address bits and the 8 mode bits), TRANS_TYPE
     * (1:0): 1 command on one line and address on four, 2 both on four */
    .equ MODE_CONTINUOUS, 0xA0
    .equ WAIT_CLOCKS, 4
    .equ SPI_CTRLR0_ENTER, (WAIT_CLOCKS << 11) | (2 << 8) | (8 << 2) | 1
    .equ SPI_CTRLR0_XIP, (MODE_CONTINUOUS << 24) | (WAIT_CLOCKS << 11) | (0 << 8) | (8 << 2) | 2

    .equ CMD_WRITE_STATUS, 0x01
    .equ CMD_READ_STATUS, 0x05
    .equ CMD_WRITE_ENABLE, 0x06
    .equ CMD_READ_STATUS2, 0x35
    .equ CMD_QUAD_READ, 0xEB
    .equ SR2_QE, 1 << 1

    .equ IMAGE_VECTORS, 0x10000100
    .equ PPB_VTOR, 0xE000ED08

    .section .text, "ax"
    .global boot2_entry
    .type boot2_entry, %function
    .thumb_func
boot2_entry:
    ldr r3, =PADS_QSPI_BASE
    movs r0, #PADS_SCLK_8MA_FAST
    str r0, [r3, #PADS_SCLK]
    ldr r0, [r3, #PADS_SD0]
    movs r1, #PADS_SCHMITT
    bics r0, r1
    str r0, [r3, #PADS_SD0]
    str r0, [r3, #PADS_SD0 + 4]
    str r0, [r3, #PADS_SD0 + 8]
    str r0, [r3, #PADS_SD0 + 12]

    ldr r3, =XIP_SSI_BASE
    movs r1, #0
    str r1, [r3, #SSI_SSIENR]
    movs r1, #BAUD_DIV
    str r1, [r3, #SSI_BAUDR]
    movs r1, #1                            /* sample a cycle late: the SDK's */
    movs r2, #SSI_RX_SAMPLE_DLY            /* beyond a Thumb store's 124-byte offset */
    str r1, [r3, r2]
    ldr r1, =CTRLR0_BYTES
    str r1, [r3, #SSI_CTRLR0]
    movs r1, #1
    str r1, [r3, #SSI_SSIENR]

    movs r0, #CMD_READ_STATUS2
    bl read_status
    movs r5, r0                            /* status register 2 */
    movs r1, #SR2_QE
    tst r5, r1
    bne quad_lines_on
    movs r0, #CMD_READ_STATUS
    bl read_status
    movs r4, r0                            /* status register 1, written back as it is */
    movs r1, #CMD_WRITE_ENABLE
    str r1, [r3, #SSI_DR0]
    bl wait_ssi_ready
    ldr r1, [r3, #SSI_DR0]
    movs r1, #CMD_WRITE_STATUS
    str r1, [r3, #SSI_DR0]
    str r4, [r3, #SSI_DR0]
    movs r1, #SR2_QE
    orrs r5, r1
    str r5, [r3, #SSI_DR0]
    bl wait_ssi_ready
    ldr r1, [r3, #SSI_DR0]
    ldr r1, [r3, #SSI_DR0]
    ldr r1, [r3, #SSI_DR0]
1:  movs r0, #CMD_READ_STATUS              /* until the write is done */
    bl read_status
    movs r1, #1                            /* BUSY */
    tst r0, r1
    bne 1b
quad_lines_on:

    movs r1, #0
    str r1, [r3, #SSI_SSIENR]
    ldr r1, =CTRLR0_QUAD_READ
    str r1, [r3, #SSI_CTRLR0]
    movs r1, #0                            /* NDF 0: one frame per read */
    str r1, [r3, #SSI_CTRLR1]
    ldr r0, =XIP_SSI_BASE + SSI_SPI_CTRLR0 /* beyond a Thumb store's 124-byte offset */
    ldr r1, =SPI_CTRLR0_ENTER
    str r1, [r0]
    movs r1, #1
    str r1, [r3, #SSI_SSIENR]
    movs r1, #CMD_QUAD_READ
    str r1, [r3, #SSI_DR0]
    movs r1, #MODE_CONTINUOUS              /* address 0, then the mode bits */
    str r1, [r3, #SSI_DR0]
    bl wait_ssi_ready
    movs r1, #0
    str r1, [r3, #SSI_SSIENR]
    ldr r1, =SPI_CTRLR0_XIP
    str r1, [r0]
    movs r1, #1
    str r1, [r3, #SSI_SSIENR]

    ldr r0, =IMAGE_VECTORS
    ldr r1, =PPB_VTOR
    str r0, [r1]
    ldmia r0!, {r1, r2}                    /* initial SP, reset handler (Thumb bit set) */
    msr msp, r1
    bx r2

/* Until the SSI has sent all it holds: the transmit FIFO empty and not busy. */
    .thumb_func
wait_ssi_ready:
    ldr r1, [r3, #SSI_SR]
    movs r2, #SR_TFE | SR_BUSY
    ands r1, r2
    cmp r1, #SR_TFE
    bne wait_ssi_ready
    bx lr

/* The status register command r0 reads: the command and one byte more, whose
 * answer is the register's value, into r0. */
    .thumb_func
read_status:
    mov r12, lr
    str r0, [r3, #SSI_DR0]
    str r0, [r3, #SSI_DR0]
    bl wait_ssi_ready
    ldr r0, [r3, #SSI_DR0]                 /* the byte the command was sent with */
    ldr r0, [r3, #SSI_DR0]
    bx r12

    .ltorg
