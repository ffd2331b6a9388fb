"""The heat model: transient conduction on the part as it is built (docs/THERMAL.md)."""
