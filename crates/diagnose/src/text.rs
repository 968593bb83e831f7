//! Numbers in running text: the report's sentences, its first paragraph and the figures'
//! labels show three significant digits and their unit.

/// A number to three significant digits for running text, without trailing zeros (`0.0466`,
/// `1.12`, `250`, `0.08`), in exponent form below 1e-4 and from 1e6; `n/a` when not finite.
pub fn sig(v: f64) -> String {
    let a = v.abs();
    if !v.is_finite() {
        "n/a".into()
    } else if a == 0.0 {
        "0".into()
    } else if (1e-4..1e6).contains(&a) {
        let decimals = (2 - a.log10().floor() as i32).max(0) as usize;
        let t = format!("{v:.decimals$}");
        if t.contains('.') { t.trim_end_matches('0').trim_end_matches('.').to_string() } else { t }
    } else {
        format!("{v:.2e}")
    }
}

/// A torque for running text: three significant digits and the unit (`0.0466 N m`).
pub fn torque_text(v: f64) -> String {
    format!("{} N m", sig(v))
}

#[cfg(test)]
mod tests {
    use super::{sig, torque_text};

    #[test]
    fn running_text_numbers_have_three_significant_digits_and_no_trailing_zeros() {
        assert_eq!(sig(0.046612), "0.0466");
        assert_eq!(sig(1.1249), "1.12");
        assert_eq!(sig(0.08), "0.08");
        assert_eq!(sig(1.0), "1");
        assert_eq!(sig(249.7), "250");
        assert_eq!(sig(-0.2213), "-0.221");
        assert_eq!(sig(2.04e-16), "2.04e-16");
        assert_eq!(sig(f64::NAN), "n/a");
        assert_eq!(torque_text(0.0105), "0.0105 N m");
    }
}
