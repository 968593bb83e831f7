//! The flags as the user typed them. clap reads an alias (`--preload`, `--step`) into its flag's
//! field and keeps no record of the name typed, so the messages name a flag by its long name
//! (`--preload-n`, `--preload-step-n`). [`TypedFlags`] reads the command line's words against
//! the command's own definition (every flag's aliases, from the clap `Command`) and restates a
//! message with the names the user typed.

use clap::Command;
use std::ffi::OsString;

/// The aliases typed on one command line: (long name, alias typed), both with their `--`.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct TypedFlags {
    pairs: Vec<(String, String)>,
}

impl TypedFlags {
    /// The aliases among `args` (the words after the program's name) of the flags of `command`
    /// and its subcommands; words after `--` are values, not flags.
    pub fn from_args(command: &Command, args: impl IntoIterator<Item = OsString>) -> Self {
        let mut pairs: Vec<(String, String)> = Vec::new();
        for word in args {
            let Some(word) = word.to_str() else { continue };
            if word == "--" {
                break;
            }
            let Some(name) = word.strip_prefix("--") else { continue };
            let name = name.split('=').next().unwrap_or(name);
            if let Some(long) = long_of_alias(command, name) {
                let (long, typed) = (format!("--{long}"), format!("--{name}"));
                pairs.retain(|(l, _)| *l != long);
                pairs.push((long, typed));
            }
        }
        Self { pairs }
    }

    /// `message` with every flag whose alias was typed named as typed.
    pub fn restate(&self, message: &str) -> String {
        self.pairs.iter().fold(message.to_string(), |m, (long, typed)| replace_flag(&m, long, typed))
    }
}

/// The long name of the flag of `command` (or of a subcommand) that has the alias `alias`.
fn long_of_alias(command: &Command, alias: &str) -> Option<String> {
    command
        .get_arguments()
        .find(|a| a.get_all_aliases().is_some_and(|all| all.contains(&alias)))
        .and_then(|a| a.get_long().map(str::to_string))
        .or_else(|| command.get_subcommands().find_map(|c| long_of_alias(c, alias)))
}

/// `text` with the flag `long` (a whole word: not followed by a letter, digit or `-`) named
/// `typed`.
fn replace_flag(text: &str, long: &str, typed: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(long) {
        let after = &rest[at + long.len()..];
        let whole = !after.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '-');
        out.push_str(&rest[..at]);
        out.push_str(if whole { typed } else { long });
        rest = after;
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Arg;

    fn command() -> Command {
        Command::new("t").subcommand(
            Command::new("sweep")
                .arg(Arg::new("p").long("preload-n").visible_alias("preload"))
                .arg(Arg::new("s").long("preload-step-n").visible_aliases(["step", "step-n"])),
        )
    }

    fn typed(words: &[&str]) -> TypedFlags {
        TypedFlags::from_args(&command(), words.iter().map(OsString::from))
    }

    #[test]
    fn a_typed_alias_names_its_flag_in_messages() {
        let t = typed(&["sweep", "--preload", "3000..500", "--step=0"]);
        assert_eq!(
            t.restate("invalid --preload-n: 3000..500; invalid --preload-step-n: 0 N"),
            "invalid --preload: 3000..500; invalid --step: 0 N"
        );
        // A long name typed, or an alias after `--`, changes nothing.
        for words in [&["sweep", "--preload-n", "1"][..], &["sweep", "--", "--step"]] {
            assert_eq!(
                typed(words).restate("invalid --preload-n or --preload-step-n"),
                "invalid --preload-n or --preload-step-n"
            );
        }
        // The last alias typed for a flag is the one named; a longer flag is another flag.
        let t = typed(&["sweep", "--step", "1", "--step-n", "2"]);
        assert_eq!(t.restate("--preload-step-n, --preload-step-nx"), "--step-n, --preload-step-nx");
    }

    /// Every alias of the command line names one flag, whichever subcommand has it.
    #[test]
    fn every_alias_of_the_command_line_names_one_flag() {
        use clap::CommandFactory as _;
        let cli = crate::Cli::command();
        let mut seen: Vec<(String, String)> = Vec::new();
        for sub in cli.get_subcommands() {
            for arg in sub.get_arguments() {
                for alias in arg.get_all_aliases().unwrap_or_default() {
                    let long = arg.get_long().unwrap_or_default().to_string();
                    if let Some((_, other)) = seen.iter().find(|(a, l)| a == alias && *l != long) {
                        panic!("--{alias} is an alias of --{long} in {} and of --{other} elsewhere", sub.get_name());
                    }
                    seen.push((alias.to_string(), long));
                }
            }
        }
        assert!(seen.iter().any(|(a, l)| a == "step" && l == "preload-step-n"), "{seen:?}");
    }
}
