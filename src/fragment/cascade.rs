//! The texture environment cascade compiled once per draw ([`Program`]): every unit's mode,
//! base format, combiner functions, sources and operands resolved into a short list of
//! eight-lane operations on registers, so that a block of eight fragments runs only the
//! arithmetic (`texenv::apply` matches on all of them per unit and per argument, and moves
//! whole colours around to do it).
//!
//! The operations are those of `texenv::apply` on the same values in the same order (the same
//! `Lanes` methods of `texenv::Avx8`), so the colours are the same bits; the only differences
//! are what is left out: arguments a function does not read and results nothing reads. `tests::program_equals_the_general_cascade` twins it against
//! `texenv::apply` on random cascades.

use super::texenv::TexEnv;
use crate::common::limits::MAX_TEXTURE_UNITS;
use crate::common::values::{CombineFunc, CombineOperand, CombineSource, TexEnvMode};
use crate::texture::format::BaseFormat;

/// A register of the program: eight lanes of one channel.
type Reg = u8;

/// Registers 0..4 hold the clamped primary colour.
const PRIMARY: [Reg; 4] = [0, 1, 2, 3];

/// What an operation computes from its arguments `a`, `b`, `c`, `d` (`args[0..4]`), its
/// scale `s` and bias; `clamp` is `clamp01`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// `1 - a` (the ONE_MINUS operands).
    OneMinus,
    /// `a b` (MODULATE).
    Mul,
    /// `a (1 - c) + b c` (DECAL of RGBA, BLEND).
    Mix,
    /// `clamp(a + b)` (ADD).
    AddClamp,
    /// `clamp(a s)`.
    Replace,
    /// `clamp(a b s)`.
    Modulate,
    /// `clamp((a + b) s)`.
    Add,
    /// `clamp((a + b - 1/2) s)`.
    AddSigned,
    /// `clamp((a c + b (1 - c)) s)`.
    Interpolate,
    /// `clamp((a - b) s)`.
    Subtract,
    /// `clamp((a b + c d - bias) s)` (COMBINE4's ADD and ADD_SIGNED).
    Sum4,
    /// `4 ((a0 - 1/2)(b0 - 1/2) + (a1 - 1/2)(b1 - 1/2) + (a2 - 1/2)(b2 - 1/2))` with
    /// `args = [a0, a1, a2, b0, b1, b2]` (DOT3, before its scale and clamp).
    Dot3,
}

impl Kind {
    /// How many of `args` the operation reads.
    fn arity(self) -> usize {
        match self {
            Kind::OneMinus | Kind::Replace => 1,
            Kind::Mul | Kind::AddClamp | Kind::Modulate | Kind::Add => 2,
            Kind::AddSigned | Kind::Subtract => 2,
            Kind::Mix | Kind::Interpolate => 3,
            Kind::Sum4 => 4,
            Kind::Dot3 => 6,
        }
    }

    /// The combiner function `f` (with a scale and the clamp).
    fn of(f: CombineFunc) -> Kind {
        match f {
            CombineFunc::Replace => Kind::Replace,
            CombineFunc::Modulate => Kind::Modulate,
            CombineFunc::Add => Kind::Add,
            CombineFunc::AddSigned => Kind::AddSigned,
            CombineFunc::Interpolate => Kind::Interpolate,
            CombineFunc::Subtract => Kind::Subtract,
            // As `texenv::combine_fn` (DOT3 is handled per vector for RGB; as an alpha
            // function it passes its first argument).
            CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => Kind::Replace,
        }
    }
}

/// One operation on `n` channels (1, or 3 for R, G, B at once): channel `j` writes register
/// `dst + j` from arguments `args[i] + j * stride[i]` (stride 1: three consecutive
/// registers; 0: one register for the three, an alpha operand).
#[derive(Clone, Copy, Debug)]
struct Op {
    kind: Kind,
    n: u8,
    dst: Reg,
    args: [Reg; 6],
    stride: [u8; 6],
    scale: f32,
    bias: f32,
}

/// The cascade of one draw's units compiled into operations (see the module comment).
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// Registers set to a constant before the operations run.
    consts: Vec<(Reg, f32)>,
    /// Registers set to a unit's texel (unit number, first of its four registers).
    texels: Vec<(usize, Reg)>,
    ops: Vec<Op>,
    /// The registers holding the result's R, G, B, A.
    out: [Reg; 4],
    /// The same cascade in the straight-line form of one `GL_COMBINE` unit, when it is one.
    single: Option<Single>,
    /// The same cascade as a chain of such forms, one per unit, when it has two units or
    /// more, all under `GL_COMBINE`, none reading another present unit's texel ([`Chain`]).
    chain: Option<Chain>,
    /// The cascade compiled for the byte route, when `bytenv::cascade_applies` takes it.
    bytes: Option<super::bytenv::Bytes>,
}

/// Where an argument of a `GL_COMBINE` unit in straight-line form ([`Single`]) comes from:
/// every source resolved for the unit (`PREVIOUS` and a crossbar read of an absent unit are the
/// incoming colour, a crossbar read of the unit itself its texel, the primary colour of the
/// first unit the incoming colour).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Src1 {
    Incoming,
    Texel,
    Constant,
    Zero,
    Primary,
}

/// One argument of a [`Single`]: its source, whether it takes the source's alpha (RGB
/// operands `SRC_ALPHA`, `ONE_MINUS_SRC_ALPHA`; every alpha operand), and whether it is
/// `1 - value`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Arg1 {
    src: Src1,
    alpha: bool,
    one_minus: bool,
}

impl Arg1 {
    /// The registers `Single::eval` reads for R, G, B (alpha: the last) from its table
    /// ([`TABLE`] entries) of the incoming colour (0..4), the texel (4..8), the constant
    /// colour (8..12), zero (12) and the primary colour (13..17).
    fn index(self) -> [u8; 3] {
        let first = match self.src {
            Src1::Incoming => 0,
            Src1::Texel => 4,
            Src1::Constant => 8,
            Src1::Zero => return [12; 3],
            Src1::Primary => 13,
        };
        if self.alpha {
            [first + 3; 3]
        } else {
            [first, first + 1, first + 2]
        }
    }
}

/// How many entries the table of `Single::eval` has (`Arg1::index`).
const TABLE: usize = 17;

/// The environment of a unit under `GL_COMBINE`, its sources resolved, for a block kernel
/// that keeps every value in registers (`Single::run`, `Single::eval`): the operations of
/// `texenv::combine` on the same values in the same order, so the same bits (twins
/// `tests::single_equals_the_general_cascade`, `tests::chain_equals_the_general_cascade`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Single {
    rgb: CombineFunc,
    alpha: CombineFunc,
    rgb_args: [Arg1; 3],
    alpha_args: [Arg1; 3],
    /// `Arg1::index` of each argument, resolved once (R, G, B; alpha arguments: the last).
    rgb_index: [[u8; 3]; 3],
    alpha_index: [u8; 3],
    rgb_scale: f32,
    alpha_scale: f32,
    constant: [f32; 4],
    /// Whether an argument `eval` reads is the constant colour (entries 8..12 of its table).
    reads_constant: bool,
}

impl Single {
    /// The straight-line form of unit `unit`'s environment `env` as the first and only unit
    /// of a cascade; `None` unless its mode is `GL_COMBINE`.
    fn new(env: &TexEnv, unit: usize) -> Option<Single> {
        let mut present = [false; MAX_TEXTURE_UNITS];
        present[unit] = true;
        Single::step(env, unit, true, &present)
    }

    /// The straight-line form of unit `unit`'s environment `env` in a cascade whose units with
    /// a texel are `present` (by unit number), `first` when it is the cascade's first unit
    /// (its incoming colour is then the primary colour); `None` unless its mode is
    /// `GL_COMBINE` and it reads no other present unit's texel.
    fn step(
        env: &TexEnv,
        unit: usize,
        first: bool,
        present: &[bool; MAX_TEXTURE_UNITS],
    ) -> Option<Single> {
        if env.mode != TexEnvMode::Combine {
            return None;
        }
        let k = &env.combine;
        // Sources the form cannot read (another present unit's texel) make it `None`.
        let mut readable = true;
        let mut src = |s: CombineSource| match s {
            CombineSource::Texture => Src1::Texel,
            CombineSource::TextureUnit(u) if u as usize == unit => Src1::Texel,
            // A unit without a texel reads as the incoming colour (`texenv::source`).
            CombineSource::TextureUnit(u) if !present.get(u as usize).copied().unwrap_or(false) => {
                Src1::Incoming
            }
            CombineSource::TextureUnit(_) => {
                readable = false;
                Src1::Zero
            }
            CombineSource::PrimaryColor if first => Src1::Incoming,
            CombineSource::PrimaryColor => Src1::Primary,
            CombineSource::Previous => Src1::Incoming,
            CombineSource::Constant => Src1::Constant,
            CombineSource::Zero => Src1::Zero,
        };
        let one_minus = |o: CombineOperand| {
            matches!(
                o,
                CombineOperand::OneMinusSrcColor | CombineOperand::OneMinusSrcAlpha
            )
        };
        let rgb_args = [0, 1, 2].map(|i| Arg1 {
            src: src(k.src_rgb[i]),
            alpha: matches!(
                k.op_rgb[i],
                CombineOperand::SrcAlpha | CombineOperand::OneMinusSrcAlpha
            ),
            one_minus: one_minus(k.op_rgb[i]),
        });
        let alpha_args = [0, 1, 2].map(|i| Arg1 {
            src: src(k.src_alpha[i]),
            alpha: true,
            one_minus: one_minus(k.op_alpha[i]),
        });
        if !readable {
            return None;
        }
        // How many arguments `eval` reads for a function.
        let reads = |f: CombineFunc| match f {
            CombineFunc::Replace => 1,
            CombineFunc::Interpolate => 3,
            _ => 2,
        };
        Some(Single {
            rgb: k.rgb,
            alpha: k.alpha,
            rgb_args,
            alpha_args,
            rgb_index: rgb_args.map(Arg1::index),
            alpha_index: alpha_args.map(|a| a.index()[2]),
            rgb_scale: k.rgb_scale as f32,
            alpha_scale: k.alpha_scale as f32,
            constant: env.color,
            reads_constant: rgb_args[..reads(k.rgb)]
                .iter()
                .chain(&alpha_args[..reads(k.alpha)])
                .any(|a| a.src == Src1::Constant),
        })
    }
}

/// A cascade of two or more `GL_COMBINE` units, each in straight-line form ([`Single`]),
/// unit after unit on registers (`Chain::run`): step `k` is the draw's `k`-th unit and reads
/// its texel, the previous step's result, the primary colour and its constant colour.
#[derive(Clone, Debug, PartialEq)]
pub struct Chain {
    steps: Vec<Single>,
}

impl Chain {
    /// The chain of `units` (environment, base format, unit number, in unit order), when
    /// there are two or more and each has a straight-line form.
    fn new(units: &[(TexEnv, BaseFormat, usize)]) -> Option<Chain> {
        if units.len() < 2 {
            return None;
        }
        let mut present = [false; MAX_TEXTURE_UNITS];
        for &(_, _, unit) in units {
            *present.get_mut(unit)? = true;
        }
        let steps = units
            .iter()
            .enumerate()
            .map(|(k, (env, _, unit))| Single::step(env, *unit, k == 0, &present))
            .collect::<Option<Vec<_>>>()?;
        Some(Chain { steps })
    }

    /// How many units (texels) the chain reads.
    pub fn len(&self) -> usize {
        self.steps.len()
    }

    /// Whether the chain has no unit (never: a chain has two or more).
    pub fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }
}

impl PartialEq for Op {
    fn eq(&self, o: &Op) -> bool {
        self.kind == o.kind
            && self.n == o.n
            && self.stride == o.stride
            && self.dst == o.dst
            && self.args == o.args
            && self.scale.to_bits() == o.scale.to_bits()
            && self.bias.to_bits() == o.bias.to_bits()
    }
}

/// The program under construction.
struct Builder {
    p: Program,
    next: usize,
}

impl Builder {
    fn reg(&mut self) -> Option<Reg> {
        let r = Reg::try_from(self.next).ok()?;
        self.next += 1;
        Some(r)
    }

    fn constant(&mut self, v: f32) -> Option<Reg> {
        if let Some(&(r, _)) = self.p.consts.iter().find(|c| c.1.to_bits() == v.to_bits()) {
            return Some(r);
        }
        let r = self.reg()?;
        self.p.consts.push((r, v));
        Some(r)
    }

    fn op(&mut self, kind: Kind, a: &[Reg], scale: f32, bias: f32) -> Option<Reg> {
        let dst = self.reg()?;
        let mut args = [0; 6];
        args[..a.len()].copy_from_slice(a);
        self.p.ops.push(Op {
            kind,
            n: 1,
            dst,
            args,
            stride: [0; 6],
            scale,
            bias,
        });
        Some(dst)
    }

    /// `kind` on R, G, B: one operation on three channels when every argument is three
    /// consecutive registers or one register three times; otherwise one per channel.
    fn op3(&mut self, kind: Kind, a: &[[Reg; 3]], scale: f32, bias: f32) -> Option<[Reg; 3]> {
        let grouped = |r: [Reg; 3]| {
            if r[1] == r[0] && r[2] == r[0] {
                Some(0)
            } else if r[1] as usize == r[0] as usize + 1 && r[2] as usize == r[0] as usize + 2 {
                Some(1)
            } else {
                None
            }
        };
        let strides: Option<Vec<u8>> = a.iter().map(|&r| grouped(r)).collect();
        let Some(strides) = strides else {
            let mut out = [0; 3];
            for (j, o) in out.iter_mut().enumerate() {
                let args: Vec<Reg> = a.iter().map(|r| r[j]).collect();
                *o = self.op(kind, &args, scale, bias)?;
            }
            return Some(out);
        };
        let dst = self.reg()?;
        let out = [dst, self.reg()?, self.reg()?];
        let mut args = [0; 6];
        let mut stride = [0; 6];
        for (i, r) in a.iter().enumerate() {
            args[i] = r[0];
            stride[i] = strides[i];
        }
        self.p.ops.push(Op {
            kind,
            n: 3,
            dst,
            args,
            stride,
            scale,
            bias,
        });
        Some(out)
    }

    fn one_minus(&mut self, a: Reg) -> Option<Reg> {
        self.op(Kind::OneMinus, &[a], 1.0, 0.0)
    }

    /// Unit `env`'s environment (as `texenv::apply`) on incoming colour `cf` and texel `ct`;
    /// `texels` are the registers of every unit's texel by unit number.
    fn unit(
        &mut self,
        env: &TexEnv,
        base: BaseFormat,
        cf: [Reg; 4],
        ct: [Reg; 4],
        texels: &[Option<[Reg; 4]>; MAX_TEXTURE_UNITS],
    ) -> Option<[Reg; 4]> {
        use BaseFormat::*;
        let (has_color, has_alpha) = match base {
            Alpha => (false, true),
            Luminance | Rgb | DepthComponent | Red | Rg => (true, false),
            LuminanceAlpha | Rgba | Intensity => (true, true),
        };
        let cc = |b: &mut Builder, i: usize| b.constant(env.color[i]);
        let mut rgb = [cf[0], cf[1], cf[2]];
        Some(match env.mode {
            TexEnvMode::Replace => {
                if has_color {
                    rgb = [ct[0], ct[1], ct[2]];
                }
                let a = if has_alpha { ct[3] } else { cf[3] };
                [rgb[0], rgb[1], rgb[2], a]
            }
            TexEnvMode::Modulate => {
                if has_color {
                    rgb = self.op3(Kind::Mul, &[rgb, [ct[0], ct[1], ct[2]]], 1.0, 0.0)?;
                }
                let a = if has_alpha {
                    self.op(Kind::Mul, &[cf[3], ct[3]], 1.0, 0.0)?
                } else {
                    cf[3]
                };
                [rgb[0], rgb[1], rgb[2], a]
            }
            TexEnvMode::Decal => match base {
                Rgb => [ct[0], ct[1], ct[2], cf[3]],
                Rgba => {
                    let args = [rgb, [ct[0], ct[1], ct[2]], [ct[3]; 3]];
                    rgb = self.op3(Kind::Mix, &args, 1.0, 0.0)?;
                    [rgb[0], rgb[1], rgb[2], cf[3]]
                }
                _ => cf,
            },
            TexEnvMode::Blend => {
                if has_color {
                    let c = [cc(self, 0)?, cc(self, 1)?, cc(self, 2)?];
                    rgb = self.op3(Kind::Mix, &[rgb, c, [ct[0], ct[1], ct[2]]], 1.0, 0.0)?;
                }
                let a = match base {
                    Intensity => {
                        let c = cc(self, 3)?;
                        self.op(Kind::Mix, &[cf[3], c, ct[3]], 1.0, 0.0)?
                    }
                    _ if has_alpha => self.op(Kind::Mul, &[cf[3], ct[3]], 1.0, 0.0)?,
                    _ => cf[3],
                };
                [rgb[0], rgb[1], rgb[2], a]
            }
            TexEnvMode::Add => {
                if has_color {
                    rgb = self.op3(Kind::AddClamp, &[rgb, [ct[0], ct[1], ct[2]]], 1.0, 0.0)?;
                }
                let a = match base {
                    Intensity => self.op(Kind::AddClamp, &[cf[3], ct[3]], 1.0, 0.0)?,
                    _ if has_alpha => self.op(Kind::Mul, &[cf[3], ct[3]], 1.0, 0.0)?,
                    _ => cf[3],
                };
                [rgb[0], rgb[1], rgb[2], a]
            }
            TexEnvMode::Combine => self.combine(env, false, cf, ct, texels)?,
            TexEnvMode::Combine4 => self.combine(env, true, cf, ct, texels)?,
        })
    }

    /// `texenv::combine`.
    fn combine(
        &mut self,
        env: &TexEnv,
        four: bool,
        cf: [Reg; 4],
        ct: [Reg; 4],
        texels: &[Option<[Reg; 4]>; MAX_TEXTURE_UNITS],
    ) -> Option<[Reg; 4]> {
        let k = &env.combine;
        let source = |b: &mut Builder, s: CombineSource| -> Option<[Reg; 4]> {
            Some(match s {
                CombineSource::Texture => ct,
                CombineSource::TextureUnit(u) => {
                    texels.get(u as usize).copied().flatten().unwrap_or(cf)
                }
                CombineSource::Constant => [
                    b.constant(env.color[0])?,
                    b.constant(env.color[1])?,
                    b.constant(env.color[2])?,
                    b.constant(env.color[3])?,
                ],
                CombineSource::PrimaryColor => PRIMARY,
                CombineSource::Previous => cf,
                CombineSource::Zero => [b.constant(0.0)?; 4],
            })
        };
        let arg_rgb = |b: &mut Builder, i: usize| -> Option<[Reg; 3]> {
            let v = source(b, k.src_rgb[i])?;
            Some(match k.op_rgb[i] {
                CombineOperand::SrcColor => [v[0], v[1], v[2]],
                CombineOperand::OneMinusSrcColor => {
                    b.op3(Kind::OneMinus, &[[v[0], v[1], v[2]]], 1.0, 0.0)?
                }
                CombineOperand::SrcAlpha => [v[3]; 3],
                CombineOperand::OneMinusSrcAlpha => [b.one_minus(v[3])?; 3],
            })
        };
        let arg_a = |b: &mut Builder, i: usize| -> Option<Reg> {
            let v = source(b, k.src_alpha[i])?;
            match k.op_alpha[i] {
                CombineOperand::SrcAlpha | CombineOperand::SrcColor => Some(v[3]),
                _ => b.one_minus(v[3]),
            }
        };
        let third = |f: CombineFunc| f == CombineFunc::Interpolate || four;
        let (rs, as_) = (k.rgb_scale as f32, k.alpha_scale as f32);
        let bias = |f: CombineFunc| {
            if f == CombineFunc::AddSigned {
                0.5
            } else {
                0.0
            }
        };
        let mut out = [0; 4];
        match k.rgb {
            CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
                let (a0, a1) = (arg_rgb(self, 0)?, arg_rgb(self, 1)?);
                let args = [a0[0], a0[1], a0[2], a1[0], a1[1], a1[2]];
                let d = self.op(Kind::Dot3, &args, 1.0, 0.0)?;
                let v = self.op(Kind::Replace, &[d], rs, 0.0)?;
                out = [v, v, v, 0];
                if k.rgb == CombineFunc::Dot3Rgba {
                    out[3] = self.op(Kind::Replace, &[d], as_, 0.0)?;
                    return Some(out);
                }
            }
            f @ (CombineFunc::Add | CombineFunc::AddSigned) if four => {
                let a: [[Reg; 3]; 4] = [
                    arg_rgb(self, 0)?,
                    arg_rgb(self, 1)?,
                    arg_rgb(self, 2)?,
                    arg_rgb(self, 3)?,
                ];
                let v = self.op3(Kind::Sum4, &a, rs, bias(f))?;
                out[..3].copy_from_slice(&v);
            }
            f => {
                let kind = Kind::of(f);
                let a0 = arg_rgb(self, 0)?;
                let a1 = if kind.arity() > 1 {
                    arg_rgb(self, 1)?
                } else {
                    a0
                };
                let a2 = if third(f) && kind.arity() > 2 {
                    arg_rgb(self, 2)?
                } else {
                    a0
                };
                let v = self.op3(kind, &[a0, a1, a2][..kind.arity()], rs, 0.0)?;
                out[..3].copy_from_slice(&v);
            }
        }
        out[3] = match k.alpha {
            f @ (CombineFunc::Add | CombineFunc::AddSigned) if four => {
                let args = [
                    arg_a(self, 0)?,
                    arg_a(self, 1)?,
                    arg_a(self, 2)?,
                    arg_a(self, 3)?,
                ];
                self.op(Kind::Sum4, &args, as_, bias(f))?
            }
            f => {
                let kind = Kind::of(f);
                let a0 = arg_a(self, 0)?;
                let a1 = if kind.arity() > 1 {
                    arg_a(self, 1)?
                } else {
                    a0
                };
                let a2 = if third(f) && kind.arity() > 2 {
                    arg_a(self, 2)?
                } else {
                    a0
                };
                self.op(kind, &[a0, a1, a2], as_, 0.0)?
            }
        };
        Some(out)
    }
}

impl Program {
    /// The program of a cascade: each unit's environment, base format and unit number, in
    /// unit order (every unit listed has a texel). `None` when it needs more registers than
    /// there are (hundreds of operations: not a cascade of eight units).
    pub fn new(units: &[(TexEnv, BaseFormat, usize)]) -> Option<Program> {
        let mut b = Builder {
            p: Program {
                consts: Vec::new(),
                texels: Vec::new(),
                ops: Vec::new(),
                out: PRIMARY,
                single: None,
                chain: None,
                bytes: None,
            },
            next: PRIMARY.len(),
        };
        let mut texels: [Option<[Reg; 4]>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
        for &(_, _, unit) in units {
            if texels.get(unit)?.is_none() {
                let first = b.reg()?;
                let regs = [first, b.reg()?, b.reg()?, b.reg()?];
                texels[unit] = Some(regs);
                b.p.texels.push((unit, first));
            }
        }
        let mut color = PRIMARY;
        for (env, base, unit) in units {
            let ct = texels[*unit]?;
            color = b.unit(env, *base, color, ct, &texels)?;
        }
        b.p.out = color;
        b.p.prune();
        if let [(env, _, unit)] = units {
            b.p.single = Single::new(env, *unit);
        }
        b.p.chain = Chain::new(units);
        b.p.bytes = super::bytenv::Bytes::new(units);
        Some(b.p)
    }

    /// Drops the operations, constants and texels nothing reads (a function's arguments the
    /// cascade computed for a unit whose result a later unit replaces).
    fn prune(&mut self) {
        let mut live = [false; 256];
        for r in self.out {
            live[r as usize] = true;
        }
        let mut kept = Vec::with_capacity(self.ops.len());
        for op in self.ops.iter().rev() {
            let n = op.n as usize;
            if (0..n).any(|j| live[op.dst as usize + j]) {
                for i in 0..op.kind.arity() {
                    for j in 0..n {
                        live[op.args[i] as usize + j * op.stride[i] as usize] = true;
                    }
                }
                kept.push(*op);
            }
        }
        kept.reverse();
        self.ops = kept;
        self.consts.retain(|&(r, _)| live[r as usize]);
        self.texels
            .retain(|&(_, r)| (r as usize..r as usize + 4).any(|c| live[c]));
    }

    /// How many operations a block runs.
    pub fn len(&self) -> usize {
        self.ops.len()
    }

    /// Whether the program has no operation (the result is inputs passed through).
    pub fn is_empty(&self) -> bool {
        self.ops.is_empty()
    }

    /// The one-unit `GL_COMBINE` form of the cascade, when it is one.
    pub fn single(&self) -> Option<&Single> {
        self.single.as_ref()
    }

    /// The cascade compiled for the byte route (`bytenv::Bytes`), when it takes it.
    pub fn bytes(&self) -> Option<&super::bytenv::Bytes> {
        self.bytes.as_ref()
    }

    /// The cascade as a chain of `GL_COMBINE` units in straight-line form, when it is one.
    pub fn chain(&self) -> Option<&Chain> {
        self.chain.as_ref()
    }

    /// The units whose texels the program reads, in the order `run_regs` takes them.
    pub fn texel_units(&self) -> impl Iterator<Item = usize> + '_ {
        self.texels.iter().map(|&(unit, _)| unit)
    }
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;
    use std::mem::MaybeUninit;

    use super::{Chain, Kind, Op, Program, Single};
    use crate::common::limits::MAX_TEXTURE_UNITS;
    use crate::common::values::CombineFunc;
    use crate::fragment::texenv::{Avx8, Lanes};
    use crate::texture::simd::Texels8;

    impl Program {
        /// The cascade on eight fragments: primary colours `primary` (clamped here, as
        /// `span::environment8` clamps them) and each unit's texels by unit number; the
        /// same bits as `texenv::apply` on `Avx8` unit after unit.
        #[target_feature(enable = "avx2")]
        pub(crate) fn run_avx2(
            &self,
            primary: &Texels8,
            by_unit: &[Option<Texels8>; MAX_TEXTURE_UNITS],
        ) -> Texels8 {
            // SAFETY (loads and stores): each array holds eight f32; unaligned access.
            let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
            let color = self.run_with(primary, |_, unit| match &by_unit[unit] {
                Some(t) => [load(&t[0]), load(&t[1]), load(&t[2]), load(&t[3])],
                None => [_mm256_setzero_ps(); 4],
            });
            let mut out = [[0f32; 8]; 4];
            for (o, c) in out.iter_mut().zip(color) {
                // SAFETY: eight f32; unaligned store.
                unsafe { _mm256_storeu_ps(o.as_mut_ptr(), c) };
            }
            out
        }

        /// [`Program::run_avx2`] with the texels in registers and the result left there:
        /// `texels[i]` is the texel of the unit of [`Program::texel_units`]' `i`-th entry
        /// (zero where `texels` is shorter). The same bits.
        #[inline]
        #[target_feature(enable = "avx2")]
        pub(crate) fn run_regs(&self, primary: &Texels8, texels: &[[__m256; 4]]) -> [__m256; 4] {
            self.run_with(primary, |i, _| {
                texels.get(i).copied().unwrap_or([_mm256_setzero_ps(); 4])
            })
        }

        /// The operations on the clamped primary colours and the texels `texel(i, unit)` of
        /// the `i`-th entry of `self.texels` (unit `unit`): the result's R, G, B, A.
        #[inline]
        #[target_feature(enable = "avx2")]
        fn run_with(
            &self,
            primary: &Texels8,
            texel: impl Fn(usize, usize) -> [__m256; 4],
        ) -> [__m256; 4] {
            // Every register an operation reads was written before it (`Program::new` hands
            // out registers in order and reads only the primary colour, texels, constants
            // and earlier results); u8 indices keep to the 256 entries.
            let mut r: File = [MaybeUninit::uninit(); 258];
            // SAFETY (loads): each array holds eight f32; unaligned access.
            let load = |a: &[f32; 8]| unsafe { _mm256_loadu_ps(a.as_ptr()) };
            for c in 0..4 {
                r[c] = MaybeUninit::new(Avx8(load(&primary[c])).clamp01().0);
            }
            for &(reg, v) in &self.consts {
                r[reg as usize] = MaybeUninit::new(_mm256_set1_ps(v));
            }
            for (i, &(unit, first)) in self.texels.iter().enumerate() {
                let t = texel(i, unit);
                for (c, v) in t.into_iter().enumerate() {
                    r[first as usize + c] = MaybeUninit::new(v);
                }
            }
            for op in &self.ops {
                if op.n == 3 {
                    step::<3>(&mut r, op);
                } else {
                    step::<1>(&mut r, op);
                }
            }
            // SAFETY: written before read (above).
            let get = |i: u8| unsafe { r[i as usize].assume_init() };
            [
                get(self.out[0]),
                get(self.out[1]),
                get(self.out[2]),
                get(self.out[3]),
            ]
        }
    }

    impl Single {
        /// The environment on eight fragments' clamped primary colours `p` and texels `t`:
        /// `texenv::combine` on `Avx8` for the first unit, the same operations in the same
        /// order.
        #[inline]
        #[target_feature(enable = "avx2")]
        pub(crate) fn run(&self, p: [__m256; 4], t: [__m256; 4]) -> [__m256; 4] {
            let z = _mm256_setzero_ps();
            let k = |c: usize| _mm256_set1_ps(self.constant[c]);
            // The first unit's primary colour is its incoming colour (`Src1::Primary` is
            // not used): entries 13..17 are not read.
            let tab: Table = [
                p[0],
                p[1],
                p[2],
                p[3],
                t[0],
                t[1],
                t[2],
                t[3],
                k(0),
                k(1),
                k(2),
                k(3),
                z,
                z,
                z,
                z,
                z,
            ];
            // SAFETY: every index of `Arg1::index` is below `TABLE`.
            unsafe { self.eval(&tab) }
        }

        /// Puts the constant colour into entries 8..12 of `tab`.
        #[inline]
        #[target_feature(enable = "avx2")]
        pub(crate) fn constants(&self, tab: &mut Table) {
            for c in 0..4 {
                tab[8 + c] = _mm256_set1_ps(self.constant[c]);
            }
        }

        /// The environment on the table `tab` (`Arg1::index`: the incoming colours, the
        /// texels, the constant colour, zero, the clamped primary colours):
        /// `texenv::combine` on `Avx8`, the same operations in the same order.
        ///
        /// # Safety
        /// AVX2 is present, and the caller is an AVX2 function (always inlined into it, as
        /// `texenv::Avx8`'s operations are, so that nothing is a call). (Every index
        /// `Single::new` and `Single::step` give is below `TABLE`.)
        #[inline(always)]
        pub(crate) unsafe fn eval(&self, tab: &Table) -> [__m256; 4] {
            let zero = Avx8::splat(0.0);
            let one = Avx8::splat(1.0);
            let half = Avx8::splat(0.5);
            // The sources by `Arg1::index` (indexed in memory: one load per argument and
            // channel, no selects).
            // SAFETY: the indices of `Arg1::index` are below `TABLE` (17).
            let at = |i: u8| Avx8(unsafe { *tab.get_unchecked(i as usize) });
            // `operand_rgb` and `operand_alpha` of the source.
            let arg_rgb = |i: usize| -> [Avx8; 3] {
                let idx = self.rgb_index[i];
                let v = [at(idx[0]), at(idx[1]), at(idx[2])];
                if self.rgb_args[i].one_minus {
                    [one.sub(v[0]), one.sub(v[1]), one.sub(v[2])]
                } else {
                    v
                }
            };
            let arg_a = |i: usize| -> Avx8 {
                let v = at(self.alpha_index[i]);
                if self.alpha_args[i].one_minus {
                    one.sub(v)
                } else {
                    v
                }
            };
            let rs = Avx8::splat(self.rgb_scale);
            let as_ = Avx8::splat(self.alpha_scale);
            let mut out = [zero; 4];
            match self.rgb {
                CombineFunc::Dot3Rgb | CombineFunc::Dot3Rgba => {
                    let (a0, a1) = (arg_rgb(0), arg_rgb(1));
                    let d = crate::fragment::texenv::dot3(a0, a1);
                    let v = d.mul(rs).clamp01();
                    out = [v, v, v, zero];
                    if self.rgb == CombineFunc::Dot3Rgba {
                        out[3] = d.mul(as_).clamp01();
                        return out.map(|c| c.0);
                    }
                }
                CombineFunc::Replace => {
                    let a0 = arg_rgb(0);
                    for i in 0..3 {
                        out[i] = a0[i].mul(rs).clamp01();
                    }
                }
                CombineFunc::Modulate => {
                    let (a0, a1) = (arg_rgb(0), arg_rgb(1));
                    for i in 0..3 {
                        out[i] = a0[i].mul(a1[i]).mul(rs).clamp01();
                    }
                }
                CombineFunc::Add => {
                    let (a0, a1) = (arg_rgb(0), arg_rgb(1));
                    for i in 0..3 {
                        out[i] = a0[i].add(a1[i]).mul(rs).clamp01();
                    }
                }
                CombineFunc::AddSigned => {
                    let (a0, a1) = (arg_rgb(0), arg_rgb(1));
                    for i in 0..3 {
                        out[i] = a0[i].add(a1[i]).sub(half).mul(rs).clamp01();
                    }
                }
                CombineFunc::Interpolate => {
                    let (a0, a1, a2) = (arg_rgb(0), arg_rgb(1), arg_rgb(2));
                    for i in 0..3 {
                        out[i] = a0[i]
                            .mul(a2[i])
                            .add(a1[i].mul(one.sub(a2[i])))
                            .mul(rs)
                            .clamp01();
                    }
                }
                CombineFunc::Subtract => {
                    let (a0, a1) = (arg_rgb(0), arg_rgb(1));
                    for i in 0..3 {
                        out[i] = a0[i].sub(a1[i]).mul(rs).clamp01();
                    }
                }
            }
            out[3] = match self.alpha {
                CombineFunc::Modulate => arg_a(0).mul(arg_a(1)),
                CombineFunc::Add => arg_a(0).add(arg_a(1)),
                CombineFunc::AddSigned => arg_a(0).add(arg_a(1)).sub(half),
                CombineFunc::Interpolate => {
                    let c = arg_a(2);
                    arg_a(0).mul(c).add(arg_a(1).mul(one.sub(c)))
                }
                CombineFunc::Subtract => arg_a(0).sub(arg_a(1)),
                // REPLACE, and DOT3 as an alpha function (`texenv::combine_fn`).
                _ => arg_a(0),
            }
            .mul(as_)
            .clamp01();
            out.map(|c| c.0)
        }
    }

    /// The table of `Single::eval`.
    pub(crate) type Table = [__m256; super::TABLE];

    impl Chain {
        /// The cascade on eight fragments: primary colours `primary` (clamped here, as
        /// `Program::run_avx2` clamps them) and texels `texels[k]` of the draw's `k`-th unit
        /// (zero where `texels` is shorter); the bits of `Program::run_avx2`.
        #[cfg(test)]
        #[target_feature(enable = "avx2")]
        pub(crate) fn run(&self, primary: &Texels8, texels: &[[__m256; 4]]) -> [__m256; 4] {
            let zero = _mm256_setzero_ps();
            let got = self.run_with(primary, |k| {
                Some(texels.get(k).copied().unwrap_or([zero; 4]))
            });
            got.unwrap_or([zero; 4])
        }

        /// [`Chain::run`] with the texels of the `k`-th unit given by `texel(k)`, asked unit
        /// after unit as the chain reaches them; `None` as soon as one is `None`.
        #[inline]
        #[target_feature(enable = "avx2")]
        pub(crate) fn run_with(
            &self,
            primary: &Texels8,
            mut texel: impl FnMut(usize) -> Option<[__m256; 4]>,
        ) -> Option<[__m256; 4]> {
            let zero = _mm256_setzero_ps();
            let mut p = [zero; 4];
            for (p, v) in p.iter_mut().zip(primary) {
                // SAFETY: eight f32; unaligned load.
                *p = Avx8(unsafe { _mm256_loadu_ps(v.as_ptr()) }).clamp01().0;
            }
            // The incoming colour, the texel, the constant colour, zero, the primary colour;
            // the texel and constant entries are written by each step before `eval` reads
            // them (zero until then).
            let mut tab: Table = [
                p[0], p[1], p[2], p[3], zero, zero, zero, zero, zero, zero, zero, zero, zero, p[0],
                p[1], p[2], p[3],
            ];
            let mut color = [zero; 4];
            for (k, step) in self.steps.iter().enumerate() {
                let t = texel(k)?;
                tab[4..8].copy_from_slice(&t);
                // (Steps that read no constant colour leave the entries as they are.)
                if step.reads_constant {
                    step.constants(&mut tab);
                }
                // SAFETY: AVX2 is present (this function's feature).
                color = unsafe { step.eval(&tab) };
                tab[..4].copy_from_slice(&color);
            }
            Some(color)
        }
    }

    /// The register file: 256 registers and two more, so that the R, G, B of a register
    /// near the end stay inside (`Program::new` checks that they are not read).
    type File = [MaybeUninit<__m256>; 258];

    /// `f` on the `N` channels of operation `op`'s first `K` arguments, into its destination.
    #[inline(always)]
    fn each<const N: usize, const K: usize>(r: &mut File, op: &Op, f: impl Fn([Avx8; K]) -> Avx8) {
        for j in 0..N {
            let v = f(std::array::from_fn(|i| {
                let reg = op.args[i] as usize + j * (op.stride[i] & 1) as usize;
                // SAFETY: `Program::new` reads only registers written before (`run_avx2`);
                // `reg` is at most 255 + 2.
                Avx8(unsafe { r[reg].assume_init() })
            }));
            r[op.dst as usize + j] = MaybeUninit::new(v.0);
        }
    }

    /// Operation `op` on its `N` channels of the register file `r`.
    #[inline(always)]
    fn step<const N: usize>(r: &mut File, op: &Op) {
        let one = Avx8::splat(1.0);
        let half = Avx8::splat(0.5);
        let s = Avx8::splat(op.scale);
        match op.kind {
            Kind::OneMinus => each::<N, 1>(r, op, |[a]| one.sub(a)),
            Kind::Replace => each::<N, 1>(r, op, |[a]| a.mul(s).clamp01()),
            Kind::Mul => each::<N, 2>(r, op, |[a, b]| a.mul(b)),
            Kind::AddClamp => each::<N, 2>(r, op, |[a, b]| a.add(b).clamp01()),
            Kind::Modulate => each::<N, 2>(r, op, |[a, b]| a.mul(b).mul(s).clamp01()),
            Kind::Add => each::<N, 2>(r, op, |[a, b]| a.add(b).mul(s).clamp01()),
            Kind::AddSigned => each::<N, 2>(r, op, |[a, b]| a.add(b).sub(half).mul(s).clamp01()),
            Kind::Subtract => each::<N, 2>(r, op, |[a, b]| a.sub(b).mul(s).clamp01()),
            Kind::Mix => each::<N, 3>(r, op, |[a, b, c]| a.mul(one.sub(c)).add(b.mul(c))),
            Kind::Interpolate => each::<N, 3>(r, op, |[a, b, c]| {
                a.mul(c).add(b.mul(one.sub(c))).mul(s).clamp01()
            }),
            Kind::Sum4 => {
                let bias = Avx8::splat(op.bias);
                each::<N, 4>(r, op, |[a, b, c, d]| {
                    a.mul(b).add(c.mul(d)).sub(bias).mul(s).clamp01()
                })
            }
            Kind::Dot3 => each::<N, 6>(r, op, |[a0, a1, a2, b0, b1, b2]| {
                Avx8::splat(4.0).mul(
                    a0.sub(half)
                        .mul(b0.sub(half))
                        .add(a1.sub(half).mul(b1.sub(half)))
                        .add(a2.sub(half).mul(b2.sub(half))),
                )
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::values::{CombineFunc as F, CombineOperand as O, CombineSource as S};
    use crate::texture::simd::Texels8;

    /// Every combiner function (the last two, DOT3_RGBA and DOT3_RGB, are RGB only).
    const FUNCS: [F; 8] = [
        F::Replace,
        F::Modulate,
        F::Add,
        F::AddSigned,
        F::Interpolate,
        F::Subtract,
        F::Dot3Rgb,
        F::Dot3Rgba,
    ];
    /// Every operand.
    const OPERANDS: [O; 4] = [
        O::SrcColor,
        O::OneMinusSrcColor,
        O::SrcAlpha,
        O::OneMinusSrcAlpha,
    ];

    /// `combine4`'s cascade: four units, one operation per unit's RGB and one per alpha.
    #[test]
    fn combine4_compiles_to_eight_operations() {
        let combine = |rgb: F, src: [S; 3], scale: u8| {
            let mut env = TexEnv {
                mode: TexEnvMode::Combine,
                ..TexEnv::default()
            };
            env.combine.rgb = rgb;
            env.combine.src_rgb[..3].copy_from_slice(&src);
            env.combine.rgb_scale = scale;
            env
        };
        let mut last = combine(F::Interpolate, [S::Previous, S::Texture, S::Constant], 1);
        last.combine.op_rgb[2] = O::SrcAlpha;
        last.color = [0.0, 0.0, 0.0, 0.8];
        let units = [
            (
                combine(F::Modulate, [S::Texture, S::PrimaryColor, S::Constant], 1),
                BaseFormat::Rgba,
                0,
            ),
            (
                combine(F::Modulate, [S::Previous, S::Texture, S::Constant], 2),
                BaseFormat::Luminance,
                1,
            ),
            (
                combine(F::AddSigned, [S::Previous, S::Texture, S::Constant], 1),
                BaseFormat::Luminance,
                2,
            ),
            (last, BaseFormat::Rgb, 3),
        ];
        let p = Program::new(&units).expect("compiles");
        assert_eq!(p.len(), 8, "{p:#?}");
        assert_eq!(p.ops.iter().filter(|op| op.n == 3).count(), 4, "{p:#?}");
    }

    /// A small deterministic generator (values in [-0.25, 1.25], to reach the clamps).
    struct Gen(u64);
    impl Gen {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            self.0
        }
        fn value(&mut self) -> f32 {
            (self.next() >> 40) as f32 / (1u64 << 24) as f32 * 1.5 - 0.25
        }
        fn pick<T: Copy>(&mut self, v: &[T]) -> T {
            v[(self.next() % v.len() as u64) as usize]
        }
    }

    /// The twin of the compiled cascade: random cascades of one to eight units (every mode,
    /// base format, combiner function, source including crossbar reads of present and absent
    /// units, operand, scale and constant colour, COMBINE4 too), random primary colours and
    /// texels (outside [0, 1] too); `run_avx2` gives the bits of `texenv::apply` on one
    /// fragment at a time, unit after unit, as `span::environment` runs it.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn program_equals_the_general_cascade() {
        use crate::fragment::texenv::{apply, CombineInputs};
        if !crate::common::cpu::available() {
            return;
        }
        let mut g = Gen(0x9E37_79B9_7F4A_7C15);
        let modes = [
            TexEnvMode::Replace,
            TexEnvMode::Modulate,
            TexEnvMode::Decal,
            TexEnvMode::Blend,
            TexEnvMode::Add,
            TexEnvMode::Combine,
            TexEnvMode::Combine,
            TexEnvMode::Combine,
            TexEnvMode::Combine4,
        ];
        let bases = [
            BaseFormat::Alpha,
            BaseFormat::Luminance,
            BaseFormat::LuminanceAlpha,
            BaseFormat::Intensity,
            BaseFormat::Rgb,
            BaseFormat::Rgba,
        ];
        let funcs = FUNCS;
        let sources = [
            S::Texture,
            S::TextureUnit(0),
            S::TextureUnit(1),
            S::TextureUnit(3),
            S::TextureUnit(6),
            S::Constant,
            S::PrimaryColor,
            S::Previous,
            S::Zero,
        ];
        let operands = OPERANDS;
        let mut ops = 0;
        for case in 0..3000 {
            let n = 1 + (g.next() % 8) as usize;
            // Unit numbers in order, some skipped.
            let mut numbers: Vec<usize> = (0..MAX_TEXTURE_UNITS)
                .filter(|_| !g.next().is_multiple_of(4))
                .collect();
            numbers.truncate(n);
            let mut units = Vec::new();
            for &unit in &numbers {
                let mut env = TexEnv {
                    mode: g.pick(&modes),
                    ..TexEnv::default()
                };
                env.color = [0; 4].map(|_| g.value().clamp(0.0, 1.0));
                if g.next().is_multiple_of(4) {
                    env.color = [0.0, 0.0, 0.0, 0.8];
                }
                let k = &mut env.combine;
                k.rgb = g.pick(&funcs);
                k.alpha = g.pick(&funcs[..6]);
                for i in 0..4 {
                    k.src_rgb[i] = g.pick(&sources);
                    k.src_alpha[i] = g.pick(&sources);
                    k.op_rgb[i] = if g.next().is_multiple_of(2) {
                        O::SrcColor
                    } else {
                        g.pick(&operands)
                    };
                    k.op_alpha[i] = g.pick(&operands);
                }
                k.rgb_scale = g.pick(&[1, 2, 4]);
                k.alpha_scale = g.pick(&[1, 2, 4]);
                units.push((env, g.pick(&bases), unit));
            }
            let program = Program::new(&units).expect("compiles");
            ops += program.len();
            let lanes = |g: &mut Gen| [0; 4].map(|_| [0; 8].map(|_| g.value()));
            let primary = lanes(&mut g);
            let mut by_unit: [Option<Texels8>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
            for &(_, _, unit) in &units {
                by_unit[unit] = Some(lanes(&mut g));
            }
            // SAFETY: AVX2 is present (checked above).
            let got = unsafe { program.run_avx2(&primary, &by_unit) };
            for j in 0..8 {
                let at = |t: &Texels8| t.map(|c| c[j]);
                let texels: [Option<[f32; 4]>; MAX_TEXTURE_UNITS] =
                    by_unit.map(|t| t.as_ref().map(at));
                let p = at(&primary).map(|c| c.max(0.0).min(1.0));
                let inputs = CombineInputs {
                    primary: p,
                    texels: &texels,
                };
                let mut color = p;
                for (env, base, unit) in &units {
                    let ct = texels[*unit].unwrap_or([0.0; 4]);
                    color = apply(env, *base, *unit, color, ct, &inputs);
                }
                // Bits up to the sign of zero (as `texenv`'s own twin).
                let bits = |v: [f32; 4]| v.map(|c| (c + 0.0).to_bits());
                assert_eq!(
                    bits(color),
                    bits(at(&got)),
                    "case {case}, lane {j}: {units:?}"
                );
            }
        }
        assert!(ops > 3000 * 4, "{ops} operations");
    }

    /// The twin of the one-unit `GL_COMBINE` form: random environments of one unit (every
    /// RGB and alpha function, DOT3 included, every source including crossbar reads of the
    /// unit itself and of absent units, every operand, scale and constant colour), random
    /// primary colours and texels (outside [0, 1] too); `Single::run` gives the bits of
    /// `texenv::apply` on one fragment at a time, as the general path runs it.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn single_equals_the_general_cascade() {
        use crate::fragment::texenv::{apply, CombineInputs};
        use std::arch::x86_64::*;
        if !crate::common::cpu::available() {
            return;
        }
        let mut g = Gen(0x2545_F491_4F6C_DD1D);
        let funcs = FUNCS;
        let operands = OPERANDS;
        let mut seen = [false; 8];
        for case in 0..4000 {
            let unit = (g.next() % MAX_TEXTURE_UNITS as u64) as usize;
            let sources = [
                S::Texture,
                S::TextureUnit(unit as u8),
                S::TextureUnit(((unit + 1) % MAX_TEXTURE_UNITS) as u8),
                S::Constant,
                S::PrimaryColor,
                S::Previous,
                S::Zero,
            ];
            let mut env = TexEnv {
                mode: TexEnvMode::Combine,
                ..TexEnv::default()
            };
            env.color = [0; 4].map(|_| g.value().clamp(0.0, 1.0));
            let k = &mut env.combine;
            k.rgb = g.pick(&funcs);
            k.alpha = g.pick(&funcs[..6]);
            for i in 0..4 {
                k.src_rgb[i] = g.pick(&sources);
                k.src_alpha[i] = g.pick(&sources);
                k.op_rgb[i] = g.pick(&operands);
                k.op_alpha[i] = g.pick(&operands);
            }
            k.rgb_scale = g.pick(&[1, 2, 4]);
            k.alpha_scale = g.pick(&[1, 2, 4]);
            let base = g.pick(&[BaseFormat::Rgba, BaseFormat::Luminance, BaseFormat::Alpha]);
            let program = Program::new(&[(env, base, unit)]).expect("compiles");
            let single = program.single().expect("one COMBINE unit");
            seen[funcs
                .iter()
                .position(|&f| f == env.combine.rgb)
                .unwrap_or(0)] = true;
            let lanes = |g: &mut Gen| [0; 4].map(|_| [0; 8].map(|_| g.value()));
            let (primary, texel) = (lanes(&mut g), lanes(&mut g));
            // SAFETY: AVX2 is present (checked above); eight f32 per load and store.
            let got = unsafe {
                let load = |a: &[f32; 8]| _mm256_loadu_ps(a.as_ptr());
                let clamp = |v: __m256| {
                    _mm256_min_ps(_mm256_max_ps(v, _mm256_setzero_ps()), _mm256_set1_ps(1.0))
                };
                let p = [0, 1, 2, 3].map(|c| clamp(load(&primary[c])));
                let t = [0, 1, 2, 3].map(|c| load(&texel[c]));
                let out = single.run(p, t);
                let mut got = [[0f32; 8]; 4];
                for (g, v) in got.iter_mut().zip(out) {
                    _mm256_storeu_ps(g.as_mut_ptr(), v);
                }
                got
            };
            for j in 0..8 {
                let at = |t: &Texels8| t.map(|c| c[j]);
                let mut texels: [Option<[f32; 4]>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
                texels[unit] = Some(at(&texel));
                let p = at(&primary).map(|c| c.max(0.0).min(1.0));
                let inputs = CombineInputs {
                    primary: p,
                    texels: &texels,
                };
                let want = apply(&env, base, unit, p, at(&texel), &inputs);
                let bits = |v: [f32; 4]| v.map(|c| (c + 0.0).to_bits());
                assert_eq!(bits(want), bits(at(&got)), "case {case}, lane {j}: {env:?}");
            }
        }
        assert_eq!(seen, [true; 8], "every RGB function drawn");
    }

    /// The twin of the chain form: random cascades of two to eight `GL_COMBINE` units (every
    /// RGB and alpha function, DOT3 included, every source: the texture, the previous and
    /// primary colours, the constant, zero, crossbar reads of the unit itself and of absent
    /// units; every operand, scale and constant colour), random primary colours and texels
    /// (outside [0, 1] too); `Chain::run` gives the bits of `texenv::apply` on one fragment at a
    /// time, unit after unit, as `span::environment` runs it. Cascades reading another
    /// present unit's texel have no chain.
    #[test]
    #[cfg(target_arch = "x86_64")]
    fn chain_equals_the_general_cascade() {
        use crate::fragment::texenv::{apply, CombineInputs};
        use std::arch::x86_64::*;
        if !crate::common::cpu::available() {
            return;
        }
        let mut g = Gen(0x6A09_E667_F3BC_C908);
        let funcs = FUNCS;
        let operands = OPERANDS;
        let (mut chains, mut without, mut primary_later) = (0, 0, 0);
        for case in 0..4000 {
            let n = 2 + (g.next() % 7) as usize;
            let mut numbers: Vec<usize> = (0..MAX_TEXTURE_UNITS)
                .filter(|_| !g.next().is_multiple_of(5))
                .collect();
            numbers.truncate(n);
            if numbers.len() < 2 {
                continue;
            }
            let absent = (0..MAX_TEXTURE_UNITS)
                .find(|u| !numbers.contains(u))
                .unwrap_or(0);
            // A crossbar read of another present unit now and then (no chain then).
            let crossbar = g.next().is_multiple_of(8);
            let mut units = Vec::new();
            for &unit in &numbers {
                let mut sources = vec![
                    S::Texture,
                    S::TextureUnit(unit as u8),
                    S::TextureUnit(absent as u8),
                    S::Constant,
                    S::PrimaryColor,
                    S::Previous,
                    S::Previous,
                    S::Zero,
                ];
                if crossbar {
                    sources.push(S::TextureUnit(g.pick(&numbers) as u8));
                }
                let mut env = TexEnv {
                    mode: TexEnvMode::Combine,
                    ..TexEnv::default()
                };
                env.color = [0; 4].map(|_| g.value().clamp(0.0, 1.0));
                let k = &mut env.combine;
                k.rgb = g.pick(&funcs);
                k.alpha = g.pick(&funcs[..6]);
                for i in 0..4 {
                    k.src_rgb[i] = g.pick(&sources);
                    k.src_alpha[i] = g.pick(&sources);
                    k.op_rgb[i] = g.pick(&operands);
                    k.op_alpha[i] = g.pick(&operands);
                }
                k.rgb_scale = g.pick(&[1, 2, 4]);
                k.alpha_scale = g.pick(&[1, 2, 4]);
                let base = g.pick(&[BaseFormat::Rgba, BaseFormat::Luminance, BaseFormat::Alpha]);
                units.push((env, base, unit));
            }
            let reads_other = units.iter().any(|(env, _, unit)| {
                let k = &env.combine;
                k.src_rgb.iter().chain(&k.src_alpha).any(|s| {
                    matches!(s, S::TextureUnit(u) if *u as usize != *unit
                        && numbers.contains(&(*u as usize)))
                })
            });
            let program = Program::new(&units).expect("compiles");
            let Some(chain) = program.chain() else {
                assert!(reads_other, "case {case}: no chain for {units:?}");
                without += 1;
                continue;
            };
            chains += 1;
            if units[1..].iter().any(|(env, _, _)| {
                let k = &env.combine;
                k.src_rgb[..2].contains(&S::PrimaryColor)
            }) {
                primary_later += 1;
            }
            let lanes = |g: &mut Gen| [0; 4].map(|_| [0; 8].map(|_| g.value()));
            let primary = lanes(&mut g);
            let texel_lanes: Vec<Texels8> = units.iter().map(|_| lanes(&mut g)).collect();
            // SAFETY: AVX2 is present (checked above); eight f32 per load and store.
            let got = unsafe {
                let load = |a: &[f32; 8]| _mm256_loadu_ps(a.as_ptr());
                let t: Vec<[__m256; 4]> = texel_lanes
                    .iter()
                    .map(|t| [0, 1, 2, 3].map(|c| load(&t[c])))
                    .collect();
                let out = chain.run(&primary, &t);
                let mut got = [[0f32; 8]; 4];
                for (g, v) in got.iter_mut().zip(out) {
                    _mm256_storeu_ps(g.as_mut_ptr(), v);
                }
                got
            };
            for j in 0..8 {
                let at = |t: &Texels8| t.map(|c| c[j]);
                let mut texels: [Option<[f32; 4]>; MAX_TEXTURE_UNITS] = [None; MAX_TEXTURE_UNITS];
                for ((_, _, unit), t) in units.iter().zip(&texel_lanes) {
                    texels[*unit] = Some(at(t));
                }
                let p = at(&primary).map(|c| c.max(0.0).min(1.0));
                let inputs = CombineInputs {
                    primary: p,
                    texels: &texels,
                };
                let mut color = p;
                for (env, base, unit) in &units {
                    let ct = texels[*unit].unwrap_or([0.0; 4]);
                    color = apply(env, *base, *unit, color, ct, &inputs);
                }
                let bits = |v: [f32; 4]| v.map(|c| (c + 0.0).to_bits());
                assert_eq!(
                    bits(color),
                    bits(at(&got)),
                    "case {case}, lane {j}: {units:?}"
                );
            }
        }
        assert!(
            chains > 3000 && without > 100,
            "{chains} chains, {without} without"
        );
        assert!(primary_later > 1000, "{primary_later}");
    }
}
