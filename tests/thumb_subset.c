/* thumb_subset.c: the Cortex-M0+ subset of thumb_subset.h. */
#include "thumb_subset.h"

#include <stdio.h>

static uint16_t halfword_at(const thumb_memory *m, uint32_t address)
{
    const uint32_t k = address - m->code_base;
    return (uint16_t)(m->code[k] | (m->code[k + 1] << 8));
}

static void set_nz(thumb_core *c, uint32_t v)
{
    c->z = v == 0u;
    c->n = (v >> 31) != 0u;
}

static int fault(thumb_core *c, const char *what, uint32_t pc, uint16_t op)
{
    snprintf(c->fault, sizeof c->fault, "%s at 0x%08x (0x%04x)", what, pc, op);
    return -1;
}

static int in_code(const thumb_memory *m, uint32_t address)
{
    return address >= m->code_base && address + 2u <= m->code_base + m->code_size;
}

/* The register-to-register ALU operations boot2 uses (format 4). */
static int alu(thumb_core *c, uint16_t op)
{
    const unsigned rd = op & 7u, rm = (op >> 3) & 7u;
    switch ((op >> 6) & 15u) {
    case 0x0: set_nz(c, c->r[rd] &= c->r[rm]); return 0;  /* ands */
    case 0x8: set_nz(c, c->r[rd] & c->r[rm]); return 0;   /* tst */
    case 0xC: set_nz(c, c->r[rd] |= c->r[rm]); return 0;  /* orrs */
    case 0xE: set_nz(c, c->r[rd] &= ~c->r[rm]); return 0; /* bics */
    default: return -1;
    }
}

/* A 32-bit instruction: bl, or msr msp. */
static int wide(thumb_core *c, const thumb_memory *m, uint32_t pc, uint16_t op)
{
    const uint16_t low = halfword_at(m, pc + 2u);
    if ((op & 0xF800u) == 0xF000u && (low & 0xD000u) == 0xD000u) { /* bl */
        const uint32_t s = (op >> 10) & 1u, j1 = (low >> 13) & 1u, j2 = (low >> 11) & 1u;
        const uint32_t i1 = !(j1 ^ s), i2 = !(j2 ^ s);
        uint32_t offset = (s << 24) | (i1 << 23) | (i2 << 22) | ((op & 0x3FFu) << 12) | ((low & 0x7FFu) << 1);
        if (s) offset |= 0xFE000000u;
        c->r[14] = (pc + 4u) | 1u;
        c->r[15] = pc + 4u + offset;
        return 0;
    }
    if ((op & 0xFFF0u) == 0xF380u && low == 0x8808u) { /* msr msp, rn */
        c->r[13] = c->r[op & 15u];
        c->r[15] = pc + 4u;
        return 0;
    }
    return fault(c, "a 32-bit instruction outside the subset", pc, op);
}

static int branch_to(thumb_core *c, uint32_t target, uint32_t pc, uint16_t op)
{
    if ((target & 1u) == 0u) return fault(c, "a bx to ARM state", pc, op);
    c->r[15] = target & ~1u;
    return 0;
}

/* One instruction at r[15]. */
static int step(thumb_core *c, const thumb_memory *m)
{
    const uint32_t pc = c->r[15];
    const uint16_t op = halfword_at(m, pc);
    c->r[15] = pc + 2u;
    if ((op & 0xF800u) == 0x0000u) { /* lsls rd, rm, #imm5 (movs rd, rm is #0) */
        set_nz(c, c->r[op & 7u] = c->r[(op >> 3) & 7u] << ((op >> 6) & 31u));
    } else if ((op & 0xF800u) == 0x2000u) { /* movs rd, #imm8 */
        set_nz(c, c->r[(op >> 8) & 7u] = op & 0xFFu);
    } else if ((op & 0xF800u) == 0x2800u) { /* cmp rn, #imm8 */
        set_nz(c, c->r[(op >> 8) & 7u] - (op & 0xFFu));
    } else if ((op & 0xF800u) == 0x4800u) { /* ldr rt, [pc, #imm8 * 4] */
        const uint32_t address = ((pc + 4u) & ~3u) + (op & 0xFFu) * 4u;
        if (address < m->code_base || address + 4u > m->code_base + m->code_size)
            return fault(c, "a literal outside the code", pc, op);
        const uint32_t k = address - m->code_base;
        c->r[(op >> 8) & 7u] = (uint32_t)m->code[k] | (uint32_t)m->code[k + 1] << 8 |
                               (uint32_t)m->code[k + 2] << 16 | (uint32_t)m->code[k + 3] << 24;
    } else if ((op & 0xF000u) == 0x6000u) { /* str / ldr rt, [rn, #imm5 * 4] */
        const uint32_t address = c->r[(op >> 3) & 7u] + ((op >> 6) & 31u) * 4u;
        if (op & 0x0800u)
            c->r[op & 7u] = m->load(m->bus, address);
        else
            m->store(m->bus, address, c->r[op & 7u]);
    } else if ((op & 0xFE00u) == 0x5000u) { /* str rt, [rn, rm] */
        m->store(m->bus, c->r[(op >> 3) & 7u] + c->r[(op >> 6) & 7u], c->r[op & 7u]);
    } else if ((op & 0xFC00u) == 0x4000u) {
        if (alu(c, op)) return fault(c, "an ALU operation outside the subset", pc, op);
    } else if ((op & 0xFF00u) == 0x4600u) { /* mov rd, rm (any registers) */
        const unsigned rd = (op & 7u) | ((op >> 4) & 8u);
        if (rd == 15u) return fault(c, "a mov to the pc", pc, op);
        c->r[rd] = c->r[(op >> 3) & 15u];
    } else if ((op & 0xFF87u) == 0x4700u) { /* bx rm */
        return branch_to(c, c->r[(op >> 3) & 15u], pc, op);
    } else if ((op & 0xF800u) == 0xC800u) { /* ldmia rn!, {list} */
        uint32_t address = c->r[(op >> 8) & 7u];
        for (unsigned k = 0; k < 8u; k++)
            if (op & (1u << k)) {
                c->r[k] = m->load(m->bus, address);
                address += 4u;
            }
        if (!(op & (1u << ((op >> 8) & 7u)))) c->r[(op >> 8) & 7u] = address;
    } else if ((op & 0xF000u) == 0xD000u && ((op >> 8) & 15u) <= 1u) { /* beq, bne */
        const int taken = ((op >> 8) & 1u) ? !c->z : c->z;
        if (taken) c->r[15] = pc + 4u + (uint32_t)((int32_t)(int8_t)(op & 0xFFu) * 2);
    } else if ((op & 0xF800u) == 0xE000u) { /* b */
        int32_t offset = (int32_t)(op & 0x7FFu);
        if (offset & 0x400) offset -= 0x800;
        c->r[15] = pc + 4u + (uint32_t)(offset * 2);
    } else if ((op & 0xE000u) == 0xE000u) {
        return wide(c, m, pc, op);
    } else {
        return fault(c, "an instruction outside the subset", pc, op);
    }
    return 0;
}

int thumb_run(thumb_core *core, const thumb_memory *memory, uint32_t entry, long steps)
{
    core->fault[0] = '\0';
    core->r[15] = entry;
    for (long k = 0; k < steps; k++) {
        if (!in_code(memory, core->r[15])) return 0;
        if (step(core, memory) != 0) return -1;
        if (core->fault[0] != '\0') return -1;
    }
    snprintf(core->fault, sizeof core->fault, "still running after %ld instructions", steps);
    return -1;
}
