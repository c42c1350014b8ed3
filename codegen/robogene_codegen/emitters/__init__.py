# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
"""One emitter per target; each turns the checked model into {file name: text}. Which function of
which emitter writes into which folder is said by codegen/generated-manifest.yaml, nowhere else."""
