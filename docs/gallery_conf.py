"""mkdocs-gallery's configuration script (``conf_script`` in mkdocs.yml):
the pictures are saved cut to their content (``bbox_inches="tight"``), as
``burmester map`` saves them, so that a legend beside the axes is shown
whole."""

from mkdocs_gallery.scrapers import matplotlib_scraper


def tight_matplotlib_scraper(block, script, **kwargs):
    """matplotlib's scraper, saving each figure cut to its content."""
    return matplotlib_scraper(block, script, bbox_inches="tight", **kwargs)


conf = {"image_scrapers": (tight_matplotlib_scraper,)}
