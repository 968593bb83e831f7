//! The uncertainty band's flags and what they resolve to: `--band [LOW,HIGH]` (`torque`,
//! `sweep`), `--samples N` and `--seed N` (with `--band`, and in `sensitivity`), turned into
//! the batch crate's [`BandSettings`]; and the band's errors on the command line's terms.

use crate::error::CliError;
use ballscrew_batch::uncertainty::{BandError, BandSettings, DEFAULT_QUANTILES, DEFAULT_SAMPLES, DEFAULT_SEED};
use ballscrew_batch::{Batch, BatchError};
use clap::Args;

/// `--band`'s percentiles when it is given without a value.
const DEFAULT_PERCENTILES: &str = "5,95";

/// What `--band` takes, for messages.
const BAND_VALID: &str = "two percentiles LOW,HIGH in [0, 100], LOW below HIGH, e.g. 5,95";

/// The sample of a band: its size and seed (`--band`'s companions; `sensitivity`'s own).
#[derive(Debug, Clone, Copy, Args)]
pub struct SampleArgs {
    /// Samples of the uncertain inputs (scrambled Sobol points), 8 to 65536 [default: 128]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub samples: Option<i64>,
    /// Seed of the sample: the same seed gives the same band on every run [default: 0]
    #[arg(long, value_name = "N", allow_negative_numbers = true)]
    pub seed: Option<i64>,
}

/// `--band [LOW,HIGH]` and its sample (`torque`, `sweep`).
#[derive(Debug, Clone, Args)]
pub struct BandArgs {
    /// Also the band of the drag torque that the spread of the spec's uncertain inputs gives
    /// (`[uncertainty]`: viscosity, roughness, friction, preload, ...): its LOW and HIGH
    /// percentiles over the sample [default when given without a value: 5,95]
    #[arg(long, value_name = "LOW,HIGH", num_args = 0..=1, default_missing_value = DEFAULT_PERCENTILES)]
    pub band: Option<String>,
    #[command(flatten)]
    pub sample: SampleArgs,
}

impl SampleArgs {
    /// The settings with the default quantiles, checked; the flags named in errors.
    pub fn settings(&self) -> Result<BandSettings, CliError> {
        let samples = match self.samples {
            None => DEFAULT_SAMPLES,
            Some(n) => u32::try_from(n)
                .ok()
                .filter(|&n| BandSettings { samples: n, ..BandSettings::default() }.validate().is_ok())
                .ok_or_else(|| {
                    CliError::Input(format!(
                        "invalid --samples: {n} (valid: {})",
                        ballscrew_batch::uncertainty::SAMPLES_VALID
                    ))
                })?,
        };
        let seed = match self.seed {
            None => DEFAULT_SEED,
            Some(s) => u32::try_from(s).map_err(|_| {
                CliError::Input(format!("invalid --seed: {s} (valid: a whole number in [0, {}])", u32::MAX))
            })?,
        };
        Ok(BandSettings { samples, seed, quantiles: DEFAULT_QUANTILES })
    }
}

impl BandArgs {
    /// The settings of `--band` (`None`: no band asked for); `--samples` or `--seed` without
    /// `--band` is refused (it would change nothing).
    pub fn settings(&self) -> Result<Option<BandSettings>, CliError> {
        let Some(text) = &self.band else {
            for (flag, given) in [("--samples", self.sample.samples.is_some()), ("--seed", self.sample.seed.is_some())]
            {
                if given {
                    return Err(CliError::Input(format!("{flag} needs --band (it sets the band's sample)")));
                }
            }
            return Ok(None);
        };
        let bad = || CliError::Input(format!("invalid --band: {text} (valid: {BAND_VALID})"));
        let (lo, hi) = text.split_once(',').ok_or_else(bad)?;
        // A percentage as the quantile it writes, rounded once (`12.3` as 0.123, as Python's
        // literal is): the decimal's exponent moved, not the number divided.
        let quantile = |s: &str| {
            let s = s.trim();
            let finite = s.parse::<f64>().is_ok_and(|p| (0.0..=100.0).contains(&p)) && !s.contains(['e', 'E']);
            finite.then(|| format!("{s}e-2").parse::<f64>().ok()).flatten()
        };
        let (lo, hi) = (quantile(lo).ok_or_else(bad)?, quantile(hi).ok_or_else(bad)?);
        if lo >= hi {
            return Err(bad());
        }
        let settings = BandSettings { quantiles: (lo, hi), ..self.sample.settings()? };
        settings.validate().map_err(|_| bad())?;
        Ok(Some(settings))
    }
}

/// The batch a band runs on: the machine's cores, nobody stopping it.
pub fn batch(settings: &BandSettings) -> Batch<'static> {
    Batch::new(settings.samples as usize)
}

/// A band's error on the command line's terms: a spread or a setting out of range is bad input
/// (exit 2), a sample the model cannot solve an evaluation error naming the sample.
pub fn error(context: &str, e: &BandError) -> CliError {
    match e {
        BandError::Setting(_) | BandError::Input(_) | BandError::Spread(_) => {
            CliError::Input(format!("{context}: {e}"))
        }
        BandError::Nominal { error, .. } => CliError::eval(context, error),
        BandError::Sample { error, .. } | BandError::End { error, .. } => match CliError::eval(context, error) {
            CliError::Input(_) => CliError::Input(format!("{context}: {e}")),
            _ => CliError::Eval(format!("{context}: {e}")),
        },
        BandError::Batch(BatchError::Point { error, .. }) => CliError::eval(context, error),
        BandError::Batch(_) => CliError::Eval(format!("{context}: {e}")),
    }
}

/// `5-95 %, 128 samples, seed 0`: how a band was sampled, for titles.
pub fn describe(settings: &BandSettings) -> String {
    let pct = |q: f64| crate::table::format_short(q * 100.0);
    format!(
        "{}-{} %, {} samples, seed {}",
        pct(settings.quantiles.0),
        pct(settings.quantiles.1),
        settings.samples,
        settings.seed
    )
}

/// The band's settings as a JSON report holds them.
pub fn json(settings: &BandSettings) -> serde_json::Value {
    serde_json::json!({
        "quantiles": [settings.quantiles.0, settings.quantiles.1],
        "samples": settings.samples,
        "seed": settings.seed,
    })
}
