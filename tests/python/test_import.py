import rigiddyn


def test_version_matches_package_metadata() -> None:
    from importlib.metadata import version

    assert rigiddyn.__version__ == version("rigiddyn")
