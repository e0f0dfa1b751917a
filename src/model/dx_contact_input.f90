!> The contact part of the deck as read, before labels are resolved: one record per
!> *CONTACT_... keyword (cards 1-3 and optional card A), the *CONTROL_CONTACT fields dynx uses,
!> *DATABASE_RCFORC and *DEFINE_BOX. Each record keeps its file index, line and keyword so
!> the contact build (dx_contact_build) reports a bad reference at the card that made it.
!> Field meanings: LS-DYNA Keyword User's Manual, Vol. I, *CONTACT, *CONTROL_CONTACT,
!> *DATABASE_OPTION (RCFORC), *DEFINE_BOX; docs/keywords.md.
module dx_contact_input
   use dx_kinds, only: wp
   implicit none
   private
   public :: contact_input_t, contact_in_t, box_in_t, CT_NODES_TO_SURFACE, &
             CT_SURFACE_TO_SURFACE, CT_ONE_WAY, CT_SINGLE_SURFACE

   !> contact algorithms (the keyword decides; AUTOMATIC_ only changes the surface orientation)
   integer, parameter :: CT_NODES_TO_SURFACE = 1    !< slave nodes against master segments
   integer, parameter :: CT_SURFACE_TO_SURFACE = 2  !< both passes (symmetric)
   integer, parameter :: CT_ONE_WAY = 3             !< slave nodes of slave segments, one pass
   integer, parameter :: CT_SINGLE_SURFACE = 4      !< every exterior node against every segment

   !> one *CONTACT_... keyword as read
   type :: contact_in_t
      integer :: label = 0                !< CID of the _ID option (0: numbered in deck order)
      character(:), allocatable :: title
      integer :: kind = CT_SURFACE_TO_SURFACE
      logical :: automatic = .false.
      integer :: ssid = 0, msid = 0, sstyp = 0, mstyp = 0, sboxid = 0, mboxid = 0
      integer :: spr = 0, mpr = 0
      real(wp) :: fs = 0.0_wp, fd = 0.0_wp, dc = 0.0_wp, vc = 0.0_wp, vdc = 0.0_wp
      integer :: penchk = 0
      real(wp) :: bt = 0.0_wp, dt = 1.0e20_wp
      real(wp) :: sfs = 1.0_wp, sfm = 1.0_wp, sst = 0.0_wp, mst = 0.0_wp
      real(wp) :: sfst = 1.0_wp, sfmt = 1.0_wp, fsf = 1.0_wp, vsf = 1.0_wp
      integer :: soft = 0
      real(wp) :: sofscl = 0.1_wp
      integer :: bsort = 10
      integer :: ifile = 0, line = 0      !< file index and line of card 1
      integer :: line2 = 0, line3 = 0     !< lines of cards 2 and 3 (0: absent)
      character(:), allocatable :: key    !< keyword as written (no '*')
   end type contact_in_t

   !> *DEFINE_BOX
   type :: box_in_t
      integer :: label = 0
      real(wp) :: lo(3) = 0.0_wp, hi(3) = 0.0_wp
      integer :: ifile = 0, line = 0
   end type box_in_t

   !> everything contact-related a deck states (empty when the deck has no contact)
   type :: contact_input_t
      type(contact_in_t), allocatable :: contacts(:)
      type(box_in_t), allocatable :: boxes(:)
      real(wp) :: slsfac = 0.1_wp         !< *CONTROL_CONTACT SLSFAC
      real(wp) :: rcforc_dt = 0.0_wp      !< *DATABASE_RCFORC DT (0: no rcforc file)
   end type contact_input_t
end module dx_contact_input
