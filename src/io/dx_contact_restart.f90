!> Restart dump and restore of the contact state (model%contact, dx_contact_types): what the
!> contact stage (dx_contact) carries from one cycle to the next, so a continued run repeats
!> the uninterrupted one bit for bit. Per interface and pass: the candidate lists of the
!> last bucket sort as they are (CSR cand_ptr/cand, the slave node normals of that sort, the
!> frequency bound w2pot, the search margin, the travel since the sort, the cycle of the
!> sort and the sort count), so the next sort falls on the same cycle and the local search
!> sees the same candidates; the per-node contact state (segment in contact, gap,
!> tangential trial force of the friction model). Set: the work of the contact forces
!> (sliding energy = -work), the next rcforc time and the rcforc size at the dump.
!> Segments, stiffnesses and the bucket grid (rebuilt at every sort) come from the deck.
!> Contact after Hallquist, Goudreau & Benson 1985 (CMAME 51:107-137); bucket sort after
!> Benson & Hallquist 1990 (CMAME 78:141-163). Datasets: docs/output-format.md.
module dx_contact_restart
   use dx_kinds, only: wp
   use dx_error, only: set_error, EXIT_INPUT
   use dx_strings, only: str
   use dx_restart_file, only: rs_file_t
   use dx_contact_types, only: contact_set_t
   use dx_append_file, only: dump_bytes
   implicit none
   private
   public :: contact_dump, contact_restore

contains

   subroutine contact_dump(rs, cs)
      type(rs_file_t), intent(inout) :: rs
      type(contact_set_t), intent(in) :: cs
      integer :: i, j
      character(:), allocatable :: p
      call rs%put('contact_ninterfaces', size(cs%iface))
      call rs%put('contact_label', cs%iface(:)%label)
      do i = 1, size(cs%iface)
         do j = 1, size(cs%iface(i)%pass)
            p = 'contact'//str(i)//'_pass'//str(j)//'_'
            associate (ps => cs%iface(i)%pass(j))
               call rs%put(p//'sort', [ps%margin, ps%moved, ps%w2pot, &
                                       real(ps%last_sort, wp), real(ps%nsort, wp)])
               call rs%put(p//'cand_ptr', ps%cand_ptr)
               if (size(ps%cand) > 0) call rs%put(p//'cand', ps%cand)
               if (allocated(ps%nnrm)) call rs%put(p//'nnrm', ps%nnrm)
               call rs%put(p//'ft', ps%ft)
               call rs%put(p//'iseg', ps%iseg)
               call rs%put(p//'gap', ps%gap)
               ! MPI runs: this rank's strip at the last sort (dx_contact_strips)
               if (allocated(ps%mine)) call rs%put(p//'strip', [ps%strip_axis, &
                                                   merge(1, 0, ps%mine)])
            end associate
         end do
      end do
      call rs%put('contact_work', cs%work)
      if (any(cs%iface(:)%wslave /= 0.0_wp) .or. any(cs%iface(:)%wmaster /= 0.0_wp)) then
         call rs%put('contact_wslave', cs%iface(:)%wslave)    ! (sleout decks only)
         call rs%put('contact_wmaster', cs%iface(:)%wmaster)
      end if
      call rs%put('contact_next_rcforc', cs%next_rcforc)
      call rs%put('contact_rcforc_bytes', dump_bytes(cs%rcforc_open, cs%rcforc_unit, &
                                                     cs%rcforc_resume))
   end subroutine contact_dump

   subroutine contact_restore(rs, cs)
      type(rs_file_t), intent(inout) :: rs
      type(contact_set_t), intent(inout) :: cs
      integer :: i, j, nc
      integer, allocatable :: strip(:)
      real(wp), allocatable :: w(:)
      real(wp) :: sort(5)
      character(:), allocatable :: p
      if (.not. rs%same_labels('contact_ninterfaces', 'contact_label', cs%iface(:)%label, &
                               'contact interfaces', 'have other ids')) return
      do i = 1, size(cs%iface)
         do j = 1, size(cs%iface(i)%pass)
            p = 'contact'//str(i)//'_pass'//str(j)//'_'
            associate (ps => cs%iface(i)%pass(j))
               sort = 0.0_wp
               call rs%get(p//'sort', sort)
               ps%margin = sort(1); ps%moved = sort(2); ps%w2pot = sort(3)
               ps%last_sort = nint(sort(4)); ps%nsort = nint(sort(5))
               ps%cand_ptr = 0
               call rs%get(p//'cand_ptr', ps%cand_ptr)
               if (.not. rs%ok()) return
               nc = ps%cand_ptr(ps%nnode + 1) - 1
               if (nc < 0 .or. ps%cand_ptr(1) /= 1 .or. any(ps%cand_ptr(2:) < &
                   ps%cand_ptr(:ps%nnode))) then
                  call set_error(rs%err, 'restart file '//rs%path//': dataset '//p// &
                     'cand_ptr is not a valid candidate index', EXIT_INPUT)
                  return
               end if
               if (allocated(ps%cand)) deallocate(ps%cand)
               allocate(ps%cand(nc))
               if (nc > 0) then
                  ps%cand = 0
                  call rs%get(p//'cand', ps%cand)
                  call check_segments(rs, ps%cand, 1, ps%nseg, p//'cand')
               end if
               if (allocated(ps%nnrm)) call rs%get(p//'nnrm', ps%nnrm)
               call rs%get(p//'ft', ps%ft)
               call rs%get(p//'iseg', ps%iseg)
               call rs%get(p//'gap', ps%gap)
               if (rs%has(p//'strip') .and. rs%ok()) then   ! an MPI rank's part
                  allocate(strip(ps%nnode + 1))
                  call rs%get(p//'strip', strip)
                  ps%strip_axis = strip(1)
                  if (allocated(ps%mine)) deallocate(ps%mine)
                  allocate(ps%mine(ps%nnode))
                  ps%mine = strip(2:) == 1
                  deallocate(strip)
               end if
               call check_segments(rs, ps%iseg, 0, ps%nseg, p//'iseg')
            end associate
            if (.not. rs%ok()) return
         end do
      end do
      call rs%get('contact_work', cs%work)
      cs%iface(:)%wslave = 0.0_wp; cs%iface(:)%wmaster = 0.0_wp
      if (rs%has('contact_wslave')) then       ! (absent: no sleout, or no work yet)
         allocate(w(size(cs%iface)))
         call rs%get('contact_wslave', w)
         cs%iface(:)%wslave = w
         call rs%get('contact_wmaster', w)
         cs%iface(:)%wmaster = w
      end if
      call rs%get('contact_next_rcforc', cs%next_rcforc)
      cs%rcforc_resume = 0
      call rs%get('contact_rcforc_bytes', cs%rcforc_resume)
      cs%rcforc_open = .false.
      cs%finished = .false.
   end subroutine contact_restore

   !> Segment indices read from dataset name must lie in lo..nseg (an input error if not).
   subroutine check_segments(rs, idx, lo, nseg, name)
      type(rs_file_t), intent(inout) :: rs
      integer, intent(in) :: idx(:), lo, nseg
      character(*), intent(in) :: name
      if (.not. rs%ok()) return
      if (any(idx < lo .or. idx > nseg)) call set_error(rs%err, 'restart file '//rs%path// &
         ': dataset '//name//' names segments this deck does not have', EXIT_INPUT)
   end subroutine check_segments
end module dx_contact_restart
