# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The register header comes from the SVD description by the generator in codegen: the committed
header is what it generates, it says what the description says, and a broken description is
refused naming the peripheral, register or field."""
from __future__ import annotations

import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "codegen"))
from robogene_codegen.emitters import svd_c  # noqa: E402

SVD = ROOT / "hardware" / "electronics" / "firmware" / "stm32" / "stm32g431.svd"
HEADER = ROOT / "hardware" / "electronics" / "firmware" / "generated" / "stm32g431_regs.h"


def test_the_committed_header_is_what_the_generator_writes():
    assert HEADER.read_text() == svd_c.render(SVD, "hardware/electronics/firmware/stm32/stm32g431.svd")


def test_derived_peripherals_get_their_parents_registers_at_their_own_base():
    text = HEADER.read_text()
    assert "#define FDCAN1_NBTP_OFFSET 0x01Cu" in text
    assert "#define TIM4_BASE 0x40000800u" in text and "#define TIM4_CCMR1 RG_REG32(TIM4_BASE + TIM4_CCMR1_OFFSET)" in text
    assert re.search(r"#define RCC_CCIPR_FDCANSEL_Msk 0x03000000u", text)


@pytest.mark.parametrize("old, new, message", [
    ('<peripheral derivedFrom="TIM1"><name>TIM4</name>', '<peripheral derivedFrom="TIM9"><name>TIM4</name>',
     "stm32g431.svd: TIM4 derives from unknown TIM9"),
    ("<name>MOE</name><bitOffset>15</bitOffset><bitWidth>1</bitWidth>",
     "<name>MOE</name><bitOffset>31</bitOffset><bitWidth>2</bitWidth>",
     "stm32g431.svd: TIM1.BDTR.MOE: bits 31..32 exceed the 32-bit register"),
    ("<name>IWDG</name><baseAddress>0x40003000</baseAddress>", "<name>IWDG</name><baseAddress>0x4000z000</baseAddress>",
     "stm32g431.svd: IWDG.baseAddress: '0x4000z000' is not a number"),
])
def test_a_broken_description_is_refused_by_name(tmp_path, old, new, message):
    text = SVD.read_text()
    assert text.count(old) == 1
    broken = tmp_path / "stm32g431.svd"
    broken.write_text(text.replace(old, new))
    with pytest.raises(svd_c.SvdError) as info:
        svd_c.render(broken, "x")
    assert str(info.value) == message
